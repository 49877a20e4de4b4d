#!/usr/bin/env python3
"""Answers plan_route with a straight route from start to goal, one waypoint per tolerance step."""
import rospy
from nav_msgs.srv import GetPlan, GetPlanResponse

MAX_WAYPOINTS = 10


def plan(request):
    response = GetPlanResponse()
    response.plan.header = request.goal.header
    waypoints = min(int(1.0 / request.tolerance), MAX_WAYPOINTS)
    response.plan.poses = [request.start] * waypoints + [request.goal]
    return response


if __name__ == "__main__":
    rospy.init_node("planner")
    rospy.Service("plan_route", GetPlan, plan)
    rospy.spin()
