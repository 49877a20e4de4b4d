#!/usr/bin/env python3
"""Goal planner: echoes each clicked point as a marker, and publishes a goal once a target is
known, from a clicked point or from the nearest obstacle cluster (either is enough)."""
import rospy
from geometry_msgs.msg import PointStamped, PoseStamped


class GoalPlanner(object):
    def __init__(self):
        self.have_target = False
        self.target = PointStamped()
        self.marker_pub = rospy.Publisher('goal_marker', PointStamped, queue_size=1)
        self.goal_pub = rospy.Publisher('goal', PoseStamped, queue_size=1)
        rospy.Subscriber('clicked_point', PointStamped, self.on_click, queue_size=1)
        rospy.Subscriber('cloud_clusters', PointStamped, self.on_cluster, queue_size=1)
        rospy.Timer(rospy.Duration(1.0), self.publish_goal)

    def on_click(self, point):
        self.target = point
        self.have_target = True
        self.marker_pub.publish(point)

    def on_cluster(self, point):
        self.target = point
        self.have_target = True

    def publish_goal(self, _event):
        if not self.have_target:
            return
        goal = PoseStamped()
        goal.header = self.target.header
        goal.pose.position = self.target.point
        goal.pose.orientation.w = 1.0
        self.goal_pub.publish(goal)


if __name__ == '__main__':
    rospy.init_node('goal_planner')
    GoalPlanner()
    rospy.spin()
