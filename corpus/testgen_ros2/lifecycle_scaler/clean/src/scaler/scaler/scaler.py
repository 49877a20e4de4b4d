"""Publishes speed_in times 0.5 on speed_out; both ports exist once the node is configured."""

import rclpy
from rclpy.lifecycle import LifecycleNode, TransitionCallbackReturn
from std_msgs.msg import Float64


class Scaler(LifecycleNode):
    def __init__(self):
        super().__init__("scaler")
        self.pub = None

    def on_configure(self, state):
        self.pub = self.create_lifecycle_publisher(Float64, "speed_out", 10)
        self.sub = self.create_subscription(Float64, "speed_in", self.on_speed, 10)
        return TransitionCallbackReturn.SUCCESS

    def on_speed(self, msg):
        self.pub.publish(Float64(data=msg.data * 0.5))


def main(args=None):
    rclpy.init(args=args)
    node = Scaler()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:  # SIGINT, as the generated test stops its nodes: a clean stop, not an error
        node.get_logger().info("stopped")
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == "__main__":
    main()
