#!/usr/bin/env python3
"""Front lidar of one robot: a scan, and a health string nobody in the fleet listens to yet."""
import rospy
from sensor_msgs.msg import LaserScan
from std_msgs.msg import String

if __name__ == '__main__':
    rospy.init_node('lidar_driver')
    scan_pub = rospy.Publisher('front/scan', LaserScan, queue_size=5)
    health_pub = rospy.Publisher('front/health', String, queue_size=1)
    rate = rospy.Rate(10.0)
    while not rospy.is_shutdown():
        scan_pub.publish(LaserScan(range_min=0.1, range_max=8.0, ranges=[2.0] * 90))
        health_pub.publish(String(data='ok'))
        rate.sleep()
