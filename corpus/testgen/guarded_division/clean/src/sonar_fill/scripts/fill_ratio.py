#!/usr/bin/env python3
"""Sonar fill ratio: publishes range / max_range of the latest Range at 10 Hz."""
import rospy
from sensor_msgs.msg import Range
from std_msgs.msg import Float32


class FillRatio:
    def __init__(self):
        self.latest = None
        self.pub = rospy.Publisher("fill_ratio", Float32, queue_size=10)
        rospy.Subscriber("sonar/front", Range, self.on_range, queue_size=10)

    def on_range(self, msg):
        self.latest = msg

    def run(self):
        rate = rospy.Rate(10)
        while not rospy.is_shutdown():
            if self.latest is not None and self.latest.max_range > 0:
                self.pub.publish(Float32(self.latest.range / self.latest.max_range))
            rate.sleep()


def main():
    rospy.init_node("fill_ratio")
    FillRatio().run()


if __name__ == "__main__":
    main()
