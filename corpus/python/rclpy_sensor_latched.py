"""rclpy: a sensor-data subscription and a latched (transient local) publisher."""
import rclpy
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile, qos_profile_sensor_data
from sensor_msgs.msg import LaserScan
from std_msgs.msg import Float32


class RangeLimits(Node):

    def __init__(self):
        super().__init__('range_limits')
        latched = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
        self.limit_pub = self.create_publisher(Float32, 'max_range', latched)
        self.scan_sub = self.create_subscription(
            LaserScan, 'scan', self.on_scan, qos_profile_sensor_data)
        self.max_range = None

    def on_scan(self, msg):
        if self.max_range != msg.range_max:
            self.max_range = msg.range_max
            self.limit_pub.publish(Float32(data=msg.range_max))


def main(args=None):
    rclpy.init(args=args)
    node = RangeLimits()
    rclpy.spin(node)
    rclpy.shutdown()


if __name__ == '__main__':
    main()
