"""Serves the fibonacci action: the first `order` numbers of the sequence, one feedback per number,
spread over a time budget of one second."""

import time

import rclpy
from rclpy.action import ActionServer, GoalResponse
from rclpy.node import Node
from test_msgs.action import Fibonacci

MAX_ORDER = 20
BUDGET = 1.0  # seconds a whole sequence may take


class Sequencer(Node):
    def __init__(self):
        super().__init__("sequencer")
        self.period = 0.0
        self.server = ActionServer(self, Fibonacci, "fibonacci", execute_callback=self.execute,
                                   goal_callback=self.accept)

    def accept(self, goal):
        self.period = BUDGET / goal.order
        return GoalResponse.ACCEPT if 0 < goal.order <= MAX_ORDER else GoalResponse.REJECT

    def execute(self, goal_handle):
        feedback = Fibonacci.Feedback()
        feedback.sequence = [0]
        while len(feedback.sequence) < goal_handle.request.order:
            feedback.sequence.append(sum(feedback.sequence[-2:]))
            goal_handle.publish_feedback(feedback)
            time.sleep(self.period)
        goal_handle.succeed()
        result = Fibonacci.Result()
        result.sequence = feedback.sequence
        return result


def main(args=None):
    rclpy.init(args=args)
    node = Sequencer()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:  # SIGINT, as the generated test stops its nodes: a clean stop, not an error
        node.get_logger().info("stopped")
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == "__main__":
    main()
