#!/usr/bin/env python3
"""Relays the scan to the topic named in a file the robot's setup writes at boot."""
import pathlib

import rospy
from sensor_msgs.msg import LaserScan

if __name__ == '__main__':
    rospy.init_node('scan_relay')
    pub = rospy.Publisher(pathlib.Path('/etc/relay_topic').read_text(), LaserScan, queue_size=1)
    rospy.Subscriber('scan', LaserScan, pub.publish)
    rospy.spin()
