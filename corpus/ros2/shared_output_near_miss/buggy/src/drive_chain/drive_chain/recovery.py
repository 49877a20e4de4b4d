"""Backs away from an obstacle: its commands are meant to go through the smoother."""

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class Recovery(Node):
    def __init__(self):
        super().__init__("recovery")
        self.pub = self.create_publisher(Twist, "cmd_vel", 10)
        self.create_timer(0.1, self.step)

    def step(self):
        command = Twist()
        command.linear.x = -0.1
        self.pub.publish(command)


def main():
    rclpy.init()
    rclpy.spin(Recovery())
    rclpy.shutdown()
