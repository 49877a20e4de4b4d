"""rclpy: a best-effort subscriber with an explicit QoSProfile."""
import rclpy
from rclpy.node import Node
from rclpy.qos import HistoryPolicy, QoSProfile, ReliabilityPolicy
from sensor_msgs.msg import Imu


class ImuListener(Node):

    def __init__(self):
        super().__init__('imu_listener')
        qos = QoSProfile(
            history=HistoryPolicy.KEEP_LAST,
            depth=5,
            reliability=ReliabilityPolicy.BEST_EFFORT,
        )
        self.subscription = self.create_subscription(Imu, 'imu/data', self.on_imu, qos)
        self.last_stamp = None

    def on_imu(self, msg):
        self.last_stamp = msg.header.stamp
        self.get_logger().debug(f'yaw rate {msg.angular_velocity.z:.3f} rad/s')


def main(args=None):
    rclpy.init(args=args)
    node = ImuListener()
    rclpy.spin(node)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
