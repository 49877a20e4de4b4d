#!/usr/bin/env python3
"""Logs the obstacles the detector reports."""
import rospy
from visualization_msgs.msg import MarkerArray


def on_obstacles(msg):
    rospy.loginfo('%d obstacles', len(msg.markers))


if __name__ == '__main__':
    rospy.init_node('obstacle_display')
    rospy.Subscriber('obstacles', MarkerArray, on_obstacles)
    rospy.spin()
