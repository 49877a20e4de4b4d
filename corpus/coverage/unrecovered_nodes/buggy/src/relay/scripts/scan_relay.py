#!/usr/bin/env python3
"""Relays the scan to a topic named on the command line."""
import sys

import rospy
from sensor_msgs.msg import LaserScan

if __name__ == '__main__':
    rospy.init_node('scan_relay')
    pub = rospy.Publisher(sys.argv[1], LaserScan, queue_size=1)
    rospy.Subscriber('scan', LaserScan, pub.publish)
    rospy.spin()
