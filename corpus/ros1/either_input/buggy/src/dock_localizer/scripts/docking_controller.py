#!/usr/bin/env python3
"""Docking controller: reports its approach state for every dock pose it receives."""
import rospy
from geometry_msgs.msg import PoseStamped
from std_msgs.msg import String


class DockingController(object):
    def __init__(self):
        self.status_pub = rospy.Publisher('dock/status', String, queue_size=1)
        rospy.Subscriber('dock_pose', PoseStamped, self.on_pose, queue_size=1)

    def on_pose(self, pose):
        state = 'docked' if pose.pose.position.x < 0.05 else 'approaching'
        self.status_pub.publish(String(data=state))


if __name__ == '__main__':
    rospy.init_node('docking_controller')
    DockingController()
    rospy.spin()
