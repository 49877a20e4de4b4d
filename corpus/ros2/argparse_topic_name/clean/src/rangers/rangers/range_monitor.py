"""Stops the robot when the front range sensor sees an obstacle closer than the safety distance."""

import rclpy
from rclpy.node import Node
from sensor_msgs.msg import Range


class RangeMonitor(Node):
    def __init__(self):
        super().__init__("range_monitor")
        self.safety_distance = self.declare_parameter("safety_distance", 0.5).value
        self.create_subscription(Range, "front/range_filtered", self.on_range, 10)

    def on_range(self, reading):
        if reading.range < self.safety_distance:
            self.get_logger().warn(f"obstacle at {reading.range:.2f} m")


def main():
    rclpy.init()
    rclpy.spin(RangeMonitor())
    rclpy.shutdown()
