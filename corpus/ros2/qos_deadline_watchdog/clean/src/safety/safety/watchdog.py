#!/usr/bin/env python3
"""Stops the robot when the controller's heartbeat misses its 0.5 s deadline."""

import rclpy
from rclpy.duration import Duration
from rclpy.node import Node
from rclpy.qos import QoSProfile, ReliabilityPolicy
from std_msgs.msg import Bool, UInt32


class Watchdog(Node):
    def __init__(self):
        super().__init__("watchdog")
        qos = QoSProfile(depth=1, reliability=ReliabilityPolicy.RELIABLE, deadline=Duration(seconds=0.5))
        self.stop_pub = self.create_publisher(Bool, "emergency_stop", 1)
        self.create_subscription(UInt32, "heartbeat", self.on_beat, qos)

    def on_beat(self, beat):
        self.stop_pub.publish(Bool(data=False))


def main():
    rclpy.init()
    rclpy.spin(Watchdog())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
