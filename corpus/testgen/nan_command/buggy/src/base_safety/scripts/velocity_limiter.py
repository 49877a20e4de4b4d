#!/usr/bin/env python3
"""Velocity limiter: scales the teleop command into the robot's limits."""
import math

import rospy
from geometry_msgs.msg import Twist

LIMIT = 0.8


def clamp(value):
    scale = min(1.0, LIMIT / abs(value)) if value else 1.0
    return value * scale


class Limiter:
    def __init__(self):
        self.pub = rospy.Publisher("cmd_vel", Twist, queue_size=10)
        rospy.Subscriber("teleop/cmd_vel", Twist, self.on_command, queue_size=10)

    def on_command(self, msg):
        out = Twist()
        out.linear.x = clamp(msg.linear.x)
        out.angular.z = clamp(msg.angular.z)
        self.pub.publish(out)


if __name__ == "__main__":
    rospy.init_node("velocity_limiter")
    Limiter()
    rospy.spin()
