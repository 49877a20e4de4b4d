"""Behavior (rclpy): an obstacle monitor that waits for its first scan before its 5 Hz timer
reports, publishes only once a calibration service has run, and says hello at start-up."""
import rclpy
from rclpy.node import Node
from sensor_msgs.msg import LaserScan
from std_msgs.msg import Float32, String
from std_srvs.srv import Trigger


class ObstacleMonitor(Node):

    def __init__(self):
        super().__init__('obstacle_monitor')
        self.scan = None
        self.calibrated = False
        self.offset = 0.0
        self.nearest_pub = self.create_publisher(Float32, 'nearest', 10)
        self.status_pub = self.create_publisher(String, 'status', 10)
        self.create_subscription(LaserScan, 'scan', self.on_scan, 10)
        self.create_service(Trigger, 'calibrate', self.on_calibrate)
        self.timer = self.create_timer(0.2, self.report)
        self.status_pub.publish(String(data='starting'))

    def on_scan(self, msg):
        self.scan = msg

    def on_calibrate(self, request, response):
        if self.scan is not None:
            self.offset = min(self.scan.ranges)
            self.calibrated = True
        response.success = self.calibrated
        return response

    def ready(self):
        return self.scan is not None and self.calibrated

    def report(self):
        if not self.ready():
            self.status_pub.publish(String(data='waiting'))
            return
        self.nearest_pub.publish(Float32(data=min(self.scan.ranges) - self.offset))


def main(args=None):
    rclpy.init(args=args)
    node = ObstacleMonitor()
    rclpy.spin(node)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
