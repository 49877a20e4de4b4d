#!/usr/bin/env python3
"""Logs the obstacles the detector reports (still written for version 1 of the detector)."""
import rospy
from geometry_msgs.msg import PoseArray


def on_obstacles(msg):
    rospy.loginfo('%d obstacles', len(msg.poses))


if __name__ == '__main__':
    rospy.init_node('obstacle_display')
    rospy.Subscriber('obstacle', PoseArray, on_obstacles)
    rospy.spin()
