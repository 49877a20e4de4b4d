"""rclpy: rclpy.create_node, with ports made by a helper that receives the topic names."""
import rclpy
from geometry_msgs.msg import Twist

MAX_SPEED = 0.5


def make_limiter(node, source, target):
    publisher = node.create_publisher(Twist, target, 10)

    def on_cmd(msg):
        msg.linear.x = max(-MAX_SPEED, min(MAX_SPEED, msg.linear.x))
        publisher.publish(msg)

    return node.create_subscription(Twist, source, on_cmd, 10)


def main(args=None):
    rclpy.init(args=args)
    node = rclpy.create_node('speed_limiter')
    subscription = make_limiter(node, 'cmd_vel_unlimited', 'cmd_vel')
    node.get_logger().info(f'limiting {subscription.topic_name} to {MAX_SPEED} m/s')
    rclpy.spin(node)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
