#!/usr/bin/env python3
"""Publishes an empty laser scan at 10 Hz."""
import rospy
from sensor_msgs.msg import LaserScan

if __name__ == '__main__':
    rospy.init_node('scan_source')
    pub = rospy.Publisher('scan', LaserScan, queue_size=1)
    rate = rospy.Rate(10)
    while not rospy.is_shutdown():
        pub.publish(LaserScan())
        rate.sleep()
