"""Drives towards the nearest object of the scan topic its parameter names."""

import rclpy
from geometry_msgs.msg import Twist
from rcl_interfaces.msg import FloatingPointRange, ParameterDescriptor
from rclpy.node import Node
from sensor_msgs.msg import LaserScan


class Follower(Node):
    def __init__(self):
        super().__init__("follower")
        scan_topic = self.declare_parameter("scan_topic", "scan").value
        speed_range = FloatingPointRange(from_value=0.0, to_value=1.0)
        self.max_speed = self.declare_parameter(
            "max_speed", 0.5, ParameterDescriptor(floating_point_range=[speed_range])).value
        self.cmd_pub = self.create_publisher(Twist, "cmd_vel", 10)
        self.scan_sub = self.create_subscription(LaserScan, scan_topic, self.on_scan, 10)

    def on_scan(self, scan):
        nearest = min(scan.ranges, default=float("inf"))
        cmd = Twist()
        cmd.linear.x = min(self.max_speed, max(0.0, nearest - 0.5))
        self.cmd_pub.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    node = Follower()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == "__main__":
    main()
