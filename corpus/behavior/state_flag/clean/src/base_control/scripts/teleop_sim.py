#!/usr/bin/env python3
"""Scripted teleoperation: a slow forward drive with a gentle weave, as a joystick would send."""
import math

import rospy
from geometry_msgs.msg import Twist


def main():
    rospy.init_node('teleop_sim')
    pub = rospy.Publisher('teleop/cmd_vel', Twist, queue_size=1)
    rate = rospy.Rate(10)
    t = 0.0
    while not rospy.is_shutdown():
        cmd = Twist()
        cmd.linear.x = 0.3
        cmd.angular.z = 0.2 * math.sin(t)
        pub.publish(cmd)
        t += 0.1
        rate.sleep()


if __name__ == '__main__':
    try:
        main()
    except rospy.ROSInterruptException:
        pass
