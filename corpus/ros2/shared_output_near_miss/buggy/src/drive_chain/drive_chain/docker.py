"""Drives the last centimetres onto the charger itself: its commands go to the base directly."""

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class Docker(Node):
    def __init__(self):
        super().__init__("docker")
        self.pub = self.create_publisher(Twist, "cmd_vel", 10)
        self.create_timer(0.1, self.step)

    def step(self):
        command = Twist()
        command.linear.x = 0.05
        self.pub.publish(command)


def main():
    rclpy.init()
    rclpy.spin(Docker())
    rclpy.shutdown()
