#!/usr/bin/env python3
"""Behavior: a local planner that waits for its first odometry, then plans on a 10 Hz timer;
a goal only shapes the plan (the publish does not wait for it)."""
import rospy
from geometry_msgs.msg import PoseStamped
from nav_msgs.msg import Odometry, Path


class LocalPlanner(object):

    def __init__(self):
        self.odom = None
        self.goal = None
        self.path_pub = rospy.Publisher("local_path", Path, queue_size=1)
        rospy.Subscriber("odom", Odometry, self.on_odom, queue_size=1)
        rospy.Subscriber("goal", PoseStamped, self.on_goal)
        self.timer = rospy.Timer(rospy.Duration(0.1), self.plan)

    def on_odom(self, msg):
        self.odom = msg

    def on_goal(self, msg):
        self.goal = msg

    def plan(self, _event):
        if self.odom is None:
            rospy.logwarn_throttle(5.0, "local planner: no odometry yet")
            return
        path = Path()
        path.header = self.odom.header
        if self.goal is not None:
            path.poses.append(self.goal)
        self.path_pub.publish(path)


if __name__ == "__main__":
    rospy.init_node("local_planner")
    LocalPlanner()
    rospy.spin()
