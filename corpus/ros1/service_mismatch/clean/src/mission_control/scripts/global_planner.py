#!/usr/bin/env python3
"""Straight-line planner that checks plans against the static map."""
import rospy
from geometry_msgs.msg import PoseStamped
from nav_msgs.msg import Path
from nav_msgs.srv import GetMap, GetPlan, GetPlanResponse


class GlobalPlanner(object):
    def __init__(self):
        self.step = rospy.get_param('~step', 0.1)
        self.grid = None
        self.get_map = rospy.ServiceProxy('static_map', GetMap)
        rospy.Service('~make_plan', GetPlan, self.make_plan)
        self.timer = rospy.Timer(rospy.Duration(1.0), self.fetch_map)

    def fetch_map(self, _event):
        if self.grid is not None:
            return
        try:
            self.get_map.wait_for_service(timeout=0.5)
            self.grid = self.get_map().map
        except (rospy.ROSException, rospy.ServiceException) as exc:
            rospy.logwarn_throttle(10.0, 'static map unavailable: %s', exc)

    def make_plan(self, req):
        path = Path()
        path.header.frame_id = req.goal.header.frame_id or 'map'
        sx, sy = req.start.pose.position.x, req.start.pose.position.y
        gx, gy = req.goal.pose.position.x, req.goal.pose.position.y
        n = max(1, int(max(abs(gx - sx), abs(gy - sy)) / self.step))
        for i in range(n + 1):
            pose = PoseStamped(header=path.header)
            pose.pose.position.x = sx + (gx - sx) * i / n
            pose.pose.position.y = sy + (gy - sy) * i / n
            path.poses.append(pose)
        return GetPlanResponse(plan=path)


if __name__ == '__main__':
    rospy.init_node('global_planner')
    GlobalPlanner()
    rospy.spin()
