"""Limits the acceleration of velocity commands."""

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class VelocitySmoother(Node):
    def __init__(self):
        super().__init__("velocity_smoother")
        self.max_step = self.declare_parameter("max_step", 0.1).value
        self.last = Twist()
        self.pub = self.create_publisher(Twist, "cmd_vel_out", 10)
        self.create_subscription(Twist, "cmd_vel_in", self.on_command, 10)

    def on_command(self, command):
        step = max(-self.max_step, min(self.max_step, command.linear.x - self.last.linear.x))
        self.last.linear.x += step
        self.last.angular.z = command.angular.z
        self.pub.publish(self.last)


def main():
    rclpy.init()
    rclpy.spin(VelocitySmoother())
    rclpy.shutdown()
