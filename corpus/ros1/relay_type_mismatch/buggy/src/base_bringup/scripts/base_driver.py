#!/usr/bin/env python3
"""Differential-drive base driver: turns stamped velocity commands into wheel speeds."""
import rospy
from geometry_msgs.msg import TwistStamped

WHEEL_SEPARATION = 0.4


class BaseDriver:
    def __init__(self):
        self.left = self.right = 0.0
        rospy.Subscriber('cmd_vel', TwistStamped, self.on_cmd, queue_size=1)

    def on_cmd(self, msg):
        v, w = msg.twist.linear.x, msg.twist.angular.z
        self.left = v - w * WHEEL_SEPARATION / 2.0
        self.right = v + w * WHEEL_SEPARATION / 2.0


def main():
    rospy.init_node('base_driver')
    BaseDriver()
    rospy.spin()


if __name__ == '__main__':
    main()
