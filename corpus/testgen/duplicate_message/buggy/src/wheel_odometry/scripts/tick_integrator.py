#!/usr/bin/env python3
"""Odometry integrator: adds each wheel tick exactly once, in sequence order."""
import queue

import rospy
from std_msgs.msg import UInt32


class Integrator:
    def __init__(self):
        self.ticks = queue.Queue()
        self.last = 0
        self.total = 0
        self.pub = rospy.Publisher("odom_ticks", UInt32, queue_size=10)
        rospy.Subscriber("wheel_tick", UInt32, self.ticks.put, queue_size=10)

    def step(self):
        while not self.ticks.empty():
            seq = self.ticks.get().data
            assert seq > self.last, f"tick {seq} after {self.last}"
            self.last = seq
            self.total += 1
            self.pub.publish(UInt32(self.total))


def main():
    rospy.init_node("tick_integrator")
    node = Integrator()
    rate = rospy.Rate(50)
    while not rospy.is_shutdown():
        node.step()
        rate.sleep()


if __name__ == "__main__":
    main()
