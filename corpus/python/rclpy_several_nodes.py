"""Two rclpy nodes in one program, spun by one executor: each class is a node of its own."""
import rclpy
from rclpy.executors import SingleThreadedExecutor
from rclpy.lifecycle import LifecycleNode
from rclpy.node import Node
from std_msgs.msg import String


class Sender(Node):
    def __init__(self):
        super().__init__('sender', enable_logger_service=True)
        self.pub = self.create_publisher(String, 'chatter', 10)


class Receiver(LifecycleNode):
    def __init__(self):
        super().__init__('receiver', namespace='inbox')

    def on_configure(self, state):
        self.sub = self.create_subscription(String, 'chatter', self.heard, 10)
        self.out = self.create_lifecycle_publisher(String, 'heard', 10)
        return super().on_configure(state)

    def heard(self, msg):
        self.out.publish(msg)


def main():
    rclpy.init()
    executor = SingleThreadedExecutor()
    for node in (Sender(), Receiver()):
        executor.add_node(node)
    executor.spin()


if __name__ == '__main__':
    main()
