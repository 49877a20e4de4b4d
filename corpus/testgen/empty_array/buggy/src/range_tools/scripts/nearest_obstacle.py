#!/usr/bin/env python3
"""Nearest obstacle: the closest range of each scan, published from the node's 20 Hz loop."""
import rospy
from sensor_msgs.msg import LaserScan
from std_msgs.msg import Float32


class Nearest:
    def __init__(self):
        self.scans = []
        self.pub = rospy.Publisher("nearest", Float32, queue_size=10)
        rospy.Subscriber("scan", LaserScan, self.on_scan, queue_size=10)

    def on_scan(self, msg):
        self.scans.append(msg)

    def step(self):
        scans, self.scans = self.scans, []
        for scan in scans:  # every scan received since the last step
            self.pub.publish(Float32(min(scan.ranges)))


def main():
    rospy.init_node("nearest_obstacle")
    node = Nearest()
    rate = rospy.Rate(20)
    while not rospy.is_shutdown():
        node.step()
        rate.sleep()


if __name__ == "__main__":
    main()
