#!/usr/bin/env python3
"""Names archlog cannot know stay explicit unknowns with file:line."""
import sys

import rospy
from std_msgs.msg import String


def topic_for(index):
    return "sensor_%d" % index


def main(argv):
    rospy.init_node("unknowns")
    rospy.Publisher(argv[1], String, queue_size=1)
    rospy.Publisher(topic_for(3), String, queue_size=1)
    for name in ("left", "right"):
        rospy.Subscriber(name + "/image", String, print)
    msg_type = String
    rospy.Publisher("typed", msg_type, queue_size=1)


main(sys.argv)
