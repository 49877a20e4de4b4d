"""Drives the wheels from velocity commands."""

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class BaseController(Node):
    def __init__(self):
        super().__init__("base_controller")
        self.wheel_base = self.declare_parameter("wheel_base", 0.3).value
        self.create_subscription(Twist, "cmd_vel", self.on_command, 10)

    def on_command(self, command):
        left = command.linear.x - command.angular.z * self.wheel_base / 2
        right = command.linear.x + command.angular.z * self.wheel_base / 2
        self.get_logger().debug(f"wheels {left:.2f} {right:.2f}")


def main():
    rclpy.init()
    rclpy.spin(BaseController())
    rclpy.shutdown()
