#!/usr/bin/env python3
"""Behavior: a reactive relay: every output is published in a callback, through helper methods,
a publisher passed as an argument, a lambda, functools.partial, callback_args and a
message_filters synchronizer."""
import functools

import message_filters
import rospy
from sensor_msgs.msg import CameraInfo, Image, Imu, Temperature
from std_msgs.msg import String


def forward(pub, msg):
    pub.publish(msg)


class Relay(object):

    def __init__(self):
        self.text_pub = rospy.Publisher("text_out", String, queue_size=10)
        self.imu_pub = rospy.Publisher("imu_out", Imu, queue_size=10)
        self.image_pub = rospy.Publisher("image_out", Image, queue_size=1)
        temperature_pub = rospy.Publisher("temperature_out", Temperature, queue_size=1)
        rospy.Subscriber("text_in", String, self.on_text)
        rospy.Subscriber("text_backup", String, self.on_text)
        rospy.Subscriber("imu_in", Imu, lambda msg: forward(self.imu_pub, msg))
        rospy.Subscriber("temperature_in", Temperature, functools.partial(self.on_temperature, temperature_pub))
        rospy.Subscriber("temperature_alt", Temperature, self.on_alternate, callback_args=temperature_pub)
        image = message_filters.Subscriber("image_in", Image)
        info = message_filters.Subscriber("camera_info", CameraInfo)
        sync = message_filters.ApproximateTimeSynchronizer([image, info], 10, 0.05)
        sync.registerCallback(self.on_pair)

    def on_text(self, msg):
        self.relay_text(msg.data.upper())

    def relay_text(self, text):
        self.emit(self.text_pub, String(data=text))

    def emit(self, pub, msg):
        pub.publish(msg)

    def on_temperature(self, pub, msg):
        forward(pub, msg)

    def on_alternate(self, msg, pub):
        pub.publish(msg)

    def on_pair(self, image, info):
        if info.width == image.width:
            self.image_pub.publish(image)


if __name__ == "__main__":
    rospy.init_node("relay")
    Relay()
    rospy.spin()
