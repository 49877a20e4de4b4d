#!/usr/bin/env python3
"""Publishes a blank image at 10 Hz."""
import rospy
from sensor_msgs.msg import Image

if __name__ == '__main__':
    rospy.init_node('camera')
    pub = rospy.Publisher('image_raw', Image, queue_size=1)
    rate = rospy.Rate(10)
    while not rospy.is_shutdown():
        pub.publish(Image(height=1, width=1, encoding='mono8', step=1, data=b'\0'))
        rate.sleep()
