#!/usr/bin/env python3
"""Pose tracker: the crawler's pose along the tunnel, from odometry, flagged while an obstacle is near."""
import rospy
from geometry_msgs.msg import PoseStamped
from nav_msgs.msg import Odometry
from std_msgs.msg import Bool


class PoseTracker(object):
    def __init__(self):
        self.blocked = False
        self.pose_pub = rospy.Publisher('tunnel_pose', PoseStamped, queue_size=1)
        rospy.Subscriber('odom', Odometry, self.on_odom, queue_size=10)
        rospy.Subscriber('obstacle', Bool, self.on_obstacle, queue_size=1)

    def on_obstacle(self, msg):
        self.blocked = msg.data

    def on_odom(self, odom):
        pose = PoseStamped()
        pose.header = odom.header
        pose.pose = odom.pose.pose
        self.pose_pub.publish(pose)


if __name__ == '__main__':
    rospy.init_node('pose_tracker')
    PoseTracker()
    rospy.spin()
