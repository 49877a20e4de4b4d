"""Publishes the laser scan with the robot's own body cut out (here, an empty scan at 10 Hz)."""

import rclpy
from rclpy.node import Node
from sensor_msgs.msg import LaserScan


class ScanFilter(Node):
    def __init__(self):
        super().__init__("scan_filter")
        self.pub = self.create_publisher(LaserScan, "scan_filtered", 10)
        self.timer = self.create_timer(0.1, self.tick)

    def tick(self):
        self.pub.publish(LaserScan())


def main(args=None):
    rclpy.init(args=args)
    node = ScanFilter()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == "__main__":
    main()
