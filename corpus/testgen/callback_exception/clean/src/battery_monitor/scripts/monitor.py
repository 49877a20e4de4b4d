#!/usr/bin/env python3
"""Battery monitor: publishes the charge level (whole percent) of the last voltage reading at 5 Hz."""
import math

import rospy
from std_msgs.msg import Float32, UInt8

EMPTY, FULL = 22.0, 25.2  # volts


class Monitor:
    def __init__(self):
        self.level = 0
        self.pub = rospy.Publisher("battery_level", UInt8, queue_size=10)
        rospy.Subscriber("battery_voltage", Float32, self.on_voltage, queue_size=10)

    def on_voltage(self, msg):
        if not math.isfinite(msg.data):
            return
        percent = int(round(100 * (msg.data - EMPTY) / (FULL - EMPTY)))
        self.level = min(max(percent, 0), 100)


def main():
    rospy.init_node("battery_monitor")
    monitor = Monitor()
    rate = rospy.Rate(5)
    while not rospy.is_shutdown():
        monitor.pub.publish(UInt8(monitor.level))
        rate.sleep()


if __name__ == "__main__":
    main()
