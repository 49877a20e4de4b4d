"""rclpy: a namespaced node whose topics come from parameter defaults (remappable at launch)."""
import rclpy
from nav_msgs.msg import Odometry
from rclpy.node import Node


class OdomRelay(Node):

    def __init__(self):
        super().__init__('odom_relay', namespace='robot1')
        input_topic = self.declare_parameter('input_topic', 'wheel/odom').value
        self.declare_parameter('output_topic', 'odom')
        output_topic = self.get_parameter('output_topic').get_parameter_value().string_value
        self.frame_id = self.declare_parameter('frame_id', 'odom').value
        self.pub = self.create_publisher(Odometry, output_topic, 10)
        self.sub = self.create_subscription(Odometry, input_topic, self.relay, 10)

    def relay(self, msg):
        msg.header.frame_id = self.frame_id
        self.pub.publish(msg)


def main(args=None):
    rclpy.init(args=args)
    node = OdomRelay()
    rclpy.spin(node)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
