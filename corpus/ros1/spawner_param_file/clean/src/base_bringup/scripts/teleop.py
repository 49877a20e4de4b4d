#!/usr/bin/env python3
"""Drives the base in a slow circle."""
import rospy
from geometry_msgs.msg import Twist

if __name__ == '__main__':
    rospy.init_node('teleop')
    pub = rospy.Publisher('mobile_base_controller/cmd_vel', Twist, queue_size=1)
    rate = rospy.Rate(10)
    while not rospy.is_shutdown():
        cmd = Twist()
        cmd.linear.x, cmd.angular.z = 0.2, 0.3
        pub.publish(cmd)
        rate.sleep()
