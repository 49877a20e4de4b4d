"""Answers plan_route with a straight route from start to goal, one waypoint per tolerance step."""

import math

import rclpy
from nav_msgs.srv import GetPlan
from rclpy.node import Node

MAX_WAYPOINTS = 10


class Planner(Node):
    def __init__(self):
        super().__init__("planner")
        self.service = self.create_service(GetPlan, "plan_route", self.plan)

    def plan(self, request, response):
        response.plan.header = request.goal.header
        if not (request.tolerance > 0 and math.isfinite(request.tolerance)):
            return response  # no plan: the tolerance is not a positive length
        waypoints = min(int(1.0 / request.tolerance), MAX_WAYPOINTS)
        response.plan.poses = [request.start] * waypoints + [request.goal]
        return response


def main(args=None):
    rclpy.init(args=args)
    node = Planner()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:  # SIGINT, as the generated test stops its nodes: a clean stop, not an error
        node.get_logger().info("stopped")
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == "__main__":
    main()
