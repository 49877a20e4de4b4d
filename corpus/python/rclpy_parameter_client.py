"""A node that reads another node's parameters: AsyncParameterClient creates a client of each of
that node's six parameter services."""
import rclpy
from rclpy.node import Node
from rclpy.parameter_client import AsyncParameterClient


def main():
    rclpy.init()
    node = Node('param_reader')
    client = AsyncParameterClient(node, 'camera_driver')
    client.wait_for_services(timeout_sec=3.0)
    rclpy.spin(node)


if __name__ == '__main__':
    main()
