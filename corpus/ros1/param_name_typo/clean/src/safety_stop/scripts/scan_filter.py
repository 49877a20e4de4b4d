#!/usr/bin/env python3
"""Publishes the laser scan with the robot's own body cut out (here, an empty scan at 10 Hz)."""
import rospy
from sensor_msgs.msg import LaserScan

if __name__ == '__main__':
    rospy.init_node('scan_filter')
    pub = rospy.Publisher('base_scan_filtered', LaserScan, queue_size=1)
    rate = rospy.Rate(10)
    while not rospy.is_shutdown():
        pub.publish(LaserScan())
        rate.sleep()
