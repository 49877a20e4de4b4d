#!/usr/bin/env python3
"""One sonar of the array: which one is the first word of its command line (default: front)."""
import sys

import rospy
from sensor_msgs.msg import Range

if __name__ == "__main__":
    argv = rospy.myargv(argv=sys.argv)
    sonar = argv[1] if len(argv) > 1 else "front"
    rospy.init_node("sonar_driver")
    readings = rospy.Publisher("sonar/" + sonar, Range, queue_size=1)
    rate = rospy.Rate(5.0)
    while not rospy.is_shutdown():
        readings.publish(Range(range=1.5, max_range=4.0))
        rate.sleep()
