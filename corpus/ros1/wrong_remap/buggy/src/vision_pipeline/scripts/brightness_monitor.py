#!/usr/bin/env python3
"""Computes the mean brightness of incoming mono8 images."""
import rospy
from sensor_msgs.msg import CameraInfo, Image
from std_msgs.msg import Float32


class BrightnessMonitor(object):
    def __init__(self):
        self.roi_fraction = rospy.get_param('~roi_fraction', 1.0)
        self.info = None
        self.pub = rospy.Publisher('mean_brightness', Float32, queue_size=10)
        self.image_sub = rospy.Subscriber('image', Image, self.on_image, queue_size=1)
        self.info_sub = rospy.Subscriber('camera_info', CameraInfo, self.on_info)

    def on_info(self, msg):
        self.info = msg

    def on_image(self, msg):
        if msg.encoding != 'mono8' or not msg.data:
            rospy.logwarn_throttle(5.0, 'unsupported encoding %s', msg.encoding)
            return
        n = max(1, int(len(msg.data) * self.roi_fraction))
        data = bytearray(msg.data[:n])
        self.pub.publish(Float32(sum(data) / (255.0 * n)))


if __name__ == '__main__':
    rospy.init_node('brightness_monitor')
    BrightnessMonitor()
    rospy.spin()
