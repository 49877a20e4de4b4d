#!/usr/bin/env python3
"""Logs the size of each blurred image."""
import rospy
from sensor_msgs.msg import Image


def show(msg):
    rospy.loginfo('%dx%d', msg.width, msg.height)


if __name__ == '__main__':
    rospy.init_node('viewer')
    rospy.Subscriber('image_blurred', Image, show)
    rospy.spin()
