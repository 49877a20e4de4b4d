#!/usr/bin/env python3
"""Drives the base from velocity commands and reports its odometry (a stand-in for the driver)."""
import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry


def main():
    rospy.init_node('base_driver')
    odom = rospy.Publisher('odom', Odometry, queue_size=10)
    rospy.Subscriber('cmd_vel', Twist, lambda msg: None)
    rate = rospy.Rate(20)
    while not rospy.is_shutdown():
        odom.publish(Odometry())
        rate.sleep()


if __name__ == '__main__':
    main()
