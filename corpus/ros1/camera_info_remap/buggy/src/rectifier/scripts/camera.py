#!/usr/bin/env python3
"""Publishes a blank image and its calibration at 10 Hz."""
import rospy
from sensor_msgs.msg import CameraInfo, Image

if __name__ == '__main__':
    rospy.init_node('camera')
    image_pub = rospy.Publisher('camera/image_raw', Image, queue_size=1)
    info_pub = rospy.Publisher('camera/info', CameraInfo, queue_size=1)
    rate = rospy.Rate(10)
    while not rospy.is_shutdown():
        image_pub.publish(Image(height=1, width=1, encoding='mono8', step=1, data=b'\0'))
        info_pub.publish(CameraInfo(height=1, width=1))
        rate.sleep()
