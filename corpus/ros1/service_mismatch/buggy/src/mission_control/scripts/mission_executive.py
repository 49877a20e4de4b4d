#!/usr/bin/env python3
"""Cycles through a list of goals and requests a plan for each one."""
import rospy
from geometry_msgs.msg import PoseStamped
from nav_msgs.msg import OccupancyGrid
from nav_msgs.srv import GetPlan

GOALS = [(1.0, 0.5), (3.0, 2.0), (0.5, 2.5)]


class MissionExecutive(object):
    def __init__(self):
        self.map_info = None
        self.index = 0
        rospy.Subscriber('map', OccupancyGrid, self.on_map)
        self.plan_client = rospy.ServiceProxy('global_planner/make_plan', GetPlan)
        rospy.Timer(rospy.Duration(rospy.get_param('~goal_period', 2.0)), self.next_goal)

    def on_map(self, grid):
        self.map_info = grid.info

    def next_goal(self, _event):
        if self.map_info is None:
            return
        start, goal = PoseStamped(), PoseStamped()
        start.header.frame_id = goal.header.frame_id = 'map'
        goal.pose.position.x, goal.pose.position.y = GOALS[self.index % len(GOALS)]
        try:
            resp = self.plan_client(start=start, goal=goal, tolerance=0.1)
            rospy.loginfo('goal %d: plan with %d poses', self.index, len(resp.plan.poses))
            self.index += 1
        except rospy.ServiceException as exc:
            rospy.logwarn('planning failed: %s', exc)


if __name__ == '__main__':
    rospy.init_node('mission_executive')
    MissionExecutive()
    rospy.spin()
