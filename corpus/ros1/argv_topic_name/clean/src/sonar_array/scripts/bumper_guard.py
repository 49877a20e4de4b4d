#!/usr/bin/env python3
"""Warns when the front sonar sees an obstacle closer than the guard distance."""
import rospy
from sensor_msgs.msg import Range


def on_range(reading):
    if reading.range < 0.3:
        rospy.logwarn("obstacle at %.2f m", reading.range)


if __name__ == "__main__":
    rospy.init_node("bumper_guard")
    rospy.Subscriber("sonar/front", Range, on_range)
    rospy.spin()
