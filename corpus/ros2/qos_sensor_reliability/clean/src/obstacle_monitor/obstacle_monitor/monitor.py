"""Reports the nearest obstacle in front of the robot and a stop flag."""

import rclpy
from rclpy.node import Node
from rclpy.qos import qos_profile_sensor_data
from sensor_msgs.msg import LaserScan
from std_msgs.msg import Bool


class ObstacleMonitor(Node):
    def __init__(self):
        super().__init__("obstacle_monitor")
        self.stop_distance = self.declare_parameter("stop_distance", 0.5).value
        self.stop_pub = self.create_publisher(Bool, "emergency_stop", 1)
        self.create_subscription(LaserScan, "front/scan", self.on_scan, qos_profile_sensor_data)

    def on_scan(self, scan):
        nearest = min((r for r in scan.ranges if r > scan.range_min), default=scan.range_max)
        self.stop_pub.publish(Bool(data=nearest < self.stop_distance))


def main():
    rclpy.init()
    rclpy.spin(ObstacleMonitor())
    rclpy.shutdown()
