#!/usr/bin/env python3
"""Relays the scan to scan_filtered."""
import rospy
from sensor_msgs.msg import LaserScan

if __name__ == '__main__':
    rospy.init_node('scan_relay')
    pub = rospy.Publisher('scan_filtered', LaserScan, queue_size=1)
    rospy.Subscriber('scan', LaserScan, pub.publish)
    rospy.spin()
