#!/usr/bin/env python3
"""Head pointer: while the navigator drives, points the head (through the head controller's action,
head_controller/point_head) at the next exhibit."""
import actionlib
import rospy
from actionlib_msgs.msg import GoalStatusArray
from control_msgs.msg import PointHeadAction, PointHeadGoal


class HeadPointer(object):
    def __init__(self):
        self.client = actionlib.SimpleActionClient('head_controller/point_head', PointHeadAction)
        rospy.Subscriber('navigate/status', GoalStatusArray, self.on_status, queue_size=1)

    def on_status(self, statuses):
        if any(s.status == 1 for s in statuses.status_list):
            self.client.send_goal(PointHeadGoal())


if __name__ == '__main__':
    rospy.init_node('head_pointer')
    HeadPointer()
    rospy.spin()
