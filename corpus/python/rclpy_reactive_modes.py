"""Behavior (rclpy): reactive outputs through lambdas, functools.partial and helper methods with
a publisher passed as an argument; a mode set by a service; an action server publishing progress."""
import functools

import rclpy
from example_interfaces.action import Fibonacci
from example_interfaces.srv import SetBool
from rclpy.action import ActionServer
from rclpy.node import Node
from std_msgs.msg import Int32, String

IDLE = 'idle'
ACTIVE = 'active'


class Counter(Node):

    def __init__(self):
        super().__init__('counter')
        self.mode = IDLE
        self.count_pub = self.create_publisher(Int32, 'count', 10)
        self.echo_pub = self.create_publisher(String, 'echo', 10)
        self.progress_pub = self.create_publisher(Int32, 'progress', 10)
        self.create_subscription(String, 'words', lambda msg: self.send(self.echo_pub, msg), 10)
        self.create_subscription(Int32, 'ticks', functools.partial(self.on_tick, 'tick'), 10)
        self.create_service(SetBool, 'activate', self.on_activate)
        self.server = ActionServer(self, Fibonacci, 'fibonacci', self.execute)

    def send(self, pub, msg):
        pub.publish(msg)

    def on_tick(self, label, msg):
        if self.mode == ACTIVE:
            self.count_pub.publish(Int32(data=msg.data))

    def on_activate(self, request, response):
        if request.data:
            self.mode = ACTIVE
        else:
            self.mode = IDLE
        response.success = True
        return response

    def execute(self, goal_handle):
        for step in range(goal_handle.request.order):
            self.progress_pub.publish(Int32(data=step))
        goal_handle.succeed()
        return Fibonacci.Result()


def main():
    rclpy.init()
    rclpy.spin(Counter())


if __name__ == '__main__':
    main()
