#!/usr/bin/env python3
"""Stands in for the base's driver: drives the wheels with the commands the mux lets through."""
import rospy
from geometry_msgs.msg import Twist


def drive(cmd):
    rospy.logdebug('wheels: %.2f m/s, %.2f rad/s', cmd.linear.x, cmd.angular.z)


if __name__ == '__main__':
    rospy.init_node('base_driver')
    rospy.Subscriber('mobile_base/commands/velocity', Twist, drive)
    rospy.spin()
