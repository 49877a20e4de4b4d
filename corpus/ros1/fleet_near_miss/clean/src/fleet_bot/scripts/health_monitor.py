#!/usr/bin/env python3
"""Logs the lidar's health; only the lead robot runs one."""
import rospy
from std_msgs.msg import String


def on_health(msg):
    if msg.data != 'ok':
        rospy.logwarn('lidar: %s', msg.data)


if __name__ == '__main__':
    rospy.init_node('health_monitor')
    rospy.Subscriber('front/health', String, on_health)
    rospy.spin()
