#!/usr/bin/env python3
"""Goal publisher: latches the mission's goal once at start-up."""
import rospy
from geometry_msgs.msg import PoseStamped


def main():
    rospy.init_node('goal_publisher')
    goal = PoseStamped()
    goal.header.frame_id = rospy.get_param('~frame_id', 'map')
    goal.header.stamp = rospy.Time.now()
    goal.pose.position.x = rospy.get_param('~x', 3.0)
    goal.pose.position.y = rospy.get_param('~y', 1.5)
    goal.pose.orientation.w = 1.0
    pub = rospy.Publisher('goal', PoseStamped, queue_size=1, latch=True)
    pub.publish(goal)
    rospy.spin()


if __name__ == '__main__':
    main()
