#!/usr/bin/env python3
"""Autonomous navigation: velocity commands into the mux's navigation input."""
import rospy
from geometry_msgs.msg import Twist

if __name__ == '__main__':
    rospy.init_node('navigator')
    pub = rospy.Publisher('cmd_vel_mux/input/navi', Twist, queue_size=1)
    rate = rospy.Rate(10)
    while not rospy.is_shutdown():
        cmd = Twist()
        cmd.linear.x = 0.2
        pub.publish(cmd)
        rate.sleep()
