"""rclpy: a service server and its client, two nodes in one process."""
import rclpy
from example_interfaces.srv import AddTwoInts
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node


class Adder(Node):

    def __init__(self):
        super().__init__('adder')
        self.srv = self.create_service(AddTwoInts, 'add_two_ints', self.add)

    def add(self, request, response):
        response.sum = request.a + request.b
        return response


class AdderClient(Node):

    def __init__(self):
        super().__init__('adder_client')
        self.cli = self.create_client(AddTwoInts, 'add_two_ints')
        self.timer = self.create_timer(1.0, self.send)

    def send(self):
        if not self.cli.service_is_ready():
            self.get_logger().info('add_two_ints not available yet')
            return
        self.cli.call_async(AddTwoInts.Request(a=2, b=3))


def main(args=None):
    rclpy.init(args=args)
    executor = MultiThreadedExecutor()
    executor.add_node(Adder())
    executor.add_node(AdderClient())
    executor.spin()


if __name__ == '__main__':
    main()
