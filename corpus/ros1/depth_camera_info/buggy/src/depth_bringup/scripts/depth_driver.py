#!/usr/bin/env python3
"""Publishes the depth camera's frames and its calibration (a stand-in for the driver)."""
import rospy
from sensor_msgs.msg import CameraInfo, Image

if __name__ == '__main__':
    rospy.init_node('depth_driver')
    image_pub = rospy.Publisher('depth/image_raw', Image, queue_size=2)
    info_pub = rospy.Publisher('calibration', CameraInfo, queue_size=2)
    rate = rospy.Rate(15)
    while not rospy.is_shutdown():
        image_pub.publish(Image())
        info_pub.publish(CameraInfo())
        rate.sleep()
