#!/usr/bin/env python3
"""Ports made in loops and comprehensions: one per element when the elements are known; one
standing for every element of a list parameter; one partly known name when the list is not known."""
import sys

import message_filters
import rospy
from sensor_msgs.msg import CameraInfo, Image
from std_msgs.msg import String

CAMERAS = ["front", "rear"]


class Rig:

    def __init__(self, extra):
        for side in CAMERAS:
            rospy.Publisher(side + "/status", String, queue_size=1)
        stereo = rospy.resolve_name("stereo")
        pairs = [(stereo + "/left/image_rect", Image), (stereo + "/left/camera_info", CameraInfo)]
        self.subs = [message_filters.Subscriber(topic, kind) for (topic, kind) in pairs]
        inputs = rospy.get_param("~inputs", None)
        if not isinstance(inputs, list):
            inputs = [inputs]
        for name in inputs:
            rospy.Subscriber(name, Image, print)
            rospy.Publisher(name + "/seen", String, queue_size=1)
        for name in rospy.get_param("~outputs", ["out_a", "out_b"]):
            rospy.Publisher(name, String, queue_size=1)
        for source in rospy.get_param("~sources"):
            rospy.Subscriber(source["topic"], String, print)
        for index, side in enumerate(CAMERAS):
            rospy.Publisher("camera_%d/%s" % (index, side), String, queue_size=1)
        for side, kind in zip(CAMERAS, (Image, CameraInfo)):
            rospy.Subscriber(side + "/raw", kind, print)
        for name in extra:
            rospy.Subscriber(name + "/compressed", String, print)
        rospy.Publisher(rospy.get_namespace() + "heartbeat", String, queue_size=1)
        {axis: rospy.Publisher("cmd/" + axis, String, queue_size=1) for axis in ("x", "y") if axis}


if __name__ == "__main__":
    rospy.init_node("rig")
    Rig(sys.argv[1:])
    rospy.spin()
