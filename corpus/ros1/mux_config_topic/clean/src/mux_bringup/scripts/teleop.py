#!/usr/bin/env python3
"""Joystick teleoperation: velocity commands into the mux's teleop input."""
import rospy
from geometry_msgs.msg import Twist

if __name__ == '__main__':
    rospy.init_node('teleop')
    pub = rospy.Publisher('cmd_vel_mux/input/teleop', Twist, queue_size=1)
    rate = rospy.Rate(10)
    while not rospy.is_shutdown():
        pub.publish(Twist())
        rate.sleep()
