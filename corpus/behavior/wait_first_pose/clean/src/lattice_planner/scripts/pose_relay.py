#!/usr/bin/env python3
"""Localisation stand-in: turns odometry into the stamped pose the planners consume."""
import rospy
from geometry_msgs.msg import PoseStamped
from nav_msgs.msg import Odometry


class PoseRelay(object):
    def __init__(self):
        self.frame = rospy.get_param('~frame_id', 'map')
        self.pose_pub = rospy.Publisher('odom_pose', PoseStamped, queue_size=1)
        rospy.Subscriber('odom', Odometry, self.on_odom, queue_size=1)

    def on_odom(self, msg):
        pose = PoseStamped()
        pose.header.stamp = msg.header.stamp
        pose.header.frame_id = self.frame
        pose.pose = msg.pose.pose
        self.pose_pub.publish(pose)


if __name__ == '__main__':
    rospy.init_node('pose_relay')
    PoseRelay()
    rospy.spin()
