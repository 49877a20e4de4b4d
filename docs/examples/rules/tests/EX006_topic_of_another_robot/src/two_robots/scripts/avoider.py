#!/usr/bin/env python3
"""Logs the nearest obstacle the robot's laser sees."""
import rospy
from sensor_msgs.msg import LaserScan


def on_scan(msg):
    rospy.loginfo('nearest obstacle %.2f m', min(msg.ranges or [float('inf')]))


if __name__ == '__main__':
    rospy.init_node('avoider')
    rospy.Subscriber('scan', LaserScan, on_scan, queue_size=1)
    rospy.spin()
