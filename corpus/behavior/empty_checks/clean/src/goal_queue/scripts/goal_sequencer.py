#!/usr/bin/env python3
"""Goal sequencer: queues incoming route waypoints and releases one goal per tick; the queue
length is reported on every tick."""
import rospy
from geometry_msgs.msg import PointStamped, PoseStamped
from std_msgs.msg import Int32


class GoalSequencer(object):
    def __init__(self):
        self.max_queue = rospy.get_param('~max_queue', 50)
        self.queue = []
        self.goal_pub = rospy.Publisher('current_goal', PointStamped, queue_size=1)
        self.length_pub = rospy.Publisher('~queue_length', Int32, queue_size=1)
        rospy.Subscriber('route_waypoints', PoseStamped, self.on_waypoint, queue_size=10)
        rospy.Timer(rospy.Duration(0.2), self.tick)

    def on_waypoint(self, msg):
        if len(self.queue) < self.max_queue:
            self.queue.append(msg)

    def tick(self, _event):
        self.length_pub.publish(Int32(data=len(self.queue)))
        if not self.queue:
            return
        waypoint = self.queue.pop(0)
        goal = PointStamped()
        goal.header = waypoint.header
        goal.point = waypoint.pose.position
        self.goal_pub.publish(goal)


if __name__ == '__main__':
    rospy.init_node('goal_sequencer')
    GoalSequencer()
    rospy.spin()
