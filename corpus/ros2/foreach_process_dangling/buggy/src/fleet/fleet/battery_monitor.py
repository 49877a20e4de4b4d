"""Publishes the robot's battery state, in the robot's namespace."""

import rclpy
from rclpy.node import Node
from sensor_msgs.msg import BatteryState


class BatteryMonitor(Node):
    def __init__(self):
        super().__init__("battery_monitor")
        self.state = self.create_publisher(BatteryState, "battery_state", 10)
        self.create_timer(1.0, self.tick)

    def tick(self):
        self.state.publish(BatteryState(percentage=0.5))


def main():
    rclpy.init()
    rclpy.spin(BatteryMonitor())
    rclpy.shutdown()
