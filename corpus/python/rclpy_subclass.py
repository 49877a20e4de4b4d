"""rclpy: a Node subclass with QoS depth, a preset, a QoSProfile, parameters, a timer and a service."""
import rclpy
from rclpy.node import Node
from rclpy.qos import QoSProfile, ReliabilityPolicy, DurabilityPolicy, qos_profile_sensor_data
from sensor_msgs.msg import LaserScan
from std_msgs.msg import String
from std_srvs.srv import Trigger


class Monitor(Node):
    def __init__(self):
        super().__init__("scan_monitor", namespace="robot")
        self.declare_parameter("topic", "scan")
        topic = self.get_parameter("topic").get_parameter_value().string_value
        latched = QoSProfile(depth=1, reliability=ReliabilityPolicy.RELIABLE,
                             durability=DurabilityPolicy.TRANSIENT_LOCAL)
        self.sub = self.create_subscription(LaserScan, topic, self.on_scan, qos_profile_sensor_data)
        self.pub = self.create_publisher(String, "status", latched)
        self.alerts = self.create_publisher(String, "~/alerts", 10)
        self.srv = self.create_service(Trigger, "reset", self.on_reset)
        self.timer = self.create_timer(0.5, self.tick)

    def on_scan(self, msg):
        self.get_logger().debug("scan with %d ranges" % len(msg.ranges))

    def on_reset(self, request, response):
        return response

    def tick(self):
        self.get_logger().debug("tick")


def main():
    rclpy.init()
    rclpy.spin(Monitor())


if __name__ == "__main__":
    main()
