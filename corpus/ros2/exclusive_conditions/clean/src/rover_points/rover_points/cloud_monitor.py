"""Counts the clouds it hears and logs how many arrived every `log_every` seconds."""

import rclpy
from sensor_msgs.msg import PointCloud2


def main():
    rclpy.init()
    node = rclpy.create_node("cloud_monitor")
    log_every = node.declare_parameter("log_every", 5).value
    heard = [0]

    def count(_cloud):
        heard[0] += 1

    def report():
        node.get_logger().info(f"{heard[0]} clouds in the last {log_every} s")
        heard[0] = 0

    node.create_subscription(PointCloud2, "points", count, 5)
    node.create_timer(float(log_every), report)
    rclpy.spin(node)
    rclpy.shutdown()
