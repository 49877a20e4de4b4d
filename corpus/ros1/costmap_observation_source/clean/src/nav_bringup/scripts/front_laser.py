#!/usr/bin/env python3
"""Publishes the front laser's scans (a stand-in for the driver)."""
import rospy
from sensor_msgs.msg import LaserScan

if __name__ == '__main__':
    rospy.init_node('front_laser')
    pub = rospy.Publisher('front_scan', LaserScan, queue_size=5)
    rate = rospy.Rate(10)
    while not rospy.is_shutdown():
        pub.publish(LaserScan())
        rate.sleep()
