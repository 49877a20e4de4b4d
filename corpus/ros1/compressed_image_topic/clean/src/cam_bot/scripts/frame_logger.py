#!/usr/bin/env python3
"""Logs the size of each compressed frame of the front camera."""
import rospy
from sensor_msgs.msg import CompressedImage


def on_frame(msg):
    rospy.loginfo('frame of %d bytes', len(msg.data))


if __name__ == '__main__':
    rospy.init_node('frame_logger')
    rospy.Subscriber('front/image_raw/compressed', CompressedImage, on_frame)
    rospy.spin()
