#!/usr/bin/env python3
"""A laser that sees nothing: publishes empty scans."""
import rospy
from sensor_msgs.msg import LaserScan

if __name__ == '__main__':
    rospy.init_node('laser')
    pub = rospy.Publisher('scan', LaserScan, queue_size=5)
    rate = rospy.Rate(10)
    while not rospy.is_shutdown():
        pub.publish(LaserScan())
        rate.sleep()
