#!/usr/bin/env python3
"""Stands in for the motor driver: logs each velocity command."""
import rospy
from geometry_msgs.msg import Twist


def on_command(command):
    rospy.loginfo('drive %.2f m/s', command.linear.x)


rospy.init_node('base_driver')
rospy.Subscriber('cmd_vel', Twist, on_command)
rospy.spin()
