"""rclpy: an action server computing a Fibonacci sequence, publishing feedback and honouring cancels."""
import time

import rclpy
from example_interfaces.action import Fibonacci
from rclpy.action import ActionServer, CancelResponse
from rclpy.node import Node


class FibonacciServer(Node):

    def __init__(self):
        super().__init__('fibonacci_server')
        self._action_server = ActionServer(
            self,
            Fibonacci,
            'fibonacci',
            execute_callback=self.execute,
            cancel_callback=lambda _goal: CancelResponse.ACCEPT)

    def execute(self, goal_handle):
        feedback = Fibonacci.Feedback()
        feedback.sequence = [0, 1]
        for i in range(1, goal_handle.request.order):
            if goal_handle.is_cancel_requested:
                goal_handle.canceled()
                return Fibonacci.Result()
            feedback.sequence.append(feedback.sequence[i] + feedback.sequence[i - 1])
            goal_handle.publish_feedback(feedback)
            time.sleep(0.5)
        goal_handle.succeed()
        return Fibonacci.Result(sequence=feedback.sequence)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(FibonacciServer())


if __name__ == '__main__':
    main()
