#!/usr/bin/env python3
"""Replays a figure-eight velocity pattern, as a stand-in for a joystick."""
import math

import rospy
from geometry_msgs.msg import Twist


def main():
    rospy.init_node('teleop')
    speed = rospy.get_param('~speed', 0.3)
    period = rospy.get_param('~period', 20.0)
    pub = rospy.Publisher('cmd_vel', Twist, queue_size=1)
    start = rospy.Time.now()
    rate = rospy.Rate(10)
    while not rospy.is_shutdown():
        t = (rospy.Time.now() - start).to_sec()
        cmd = Twist()
        cmd.linear.x = speed
        cmd.angular.z = 0.6 * math.sin(2.0 * math.pi * t / period)
        pub.publish(cmd)
        rate.sleep()


if __name__ == '__main__':
    try:
        main()
    except rospy.ROSInterruptException:
        rospy.loginfo("interrupted, shutting down")
