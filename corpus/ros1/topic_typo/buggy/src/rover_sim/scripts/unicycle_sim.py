#!/usr/bin/env python3
"""Integrates unicycle kinematics from cmd_vel and publishes odometry."""
import math

import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry


class UnicycleSim(object):
    def __init__(self):
        self.x = self.y = self.yaw = 0.0
        self.cmd = Twist()
        self.frame_id = rospy.get_param('~odom_frame', 'odom')
        self.dt = 1.0 / rospy.get_param('~rate', 20.0)
        self.pub = rospy.Publisher('odom', Odometry, queue_size=10)
        self.sub = rospy.Subscriber('cmd_vel', Twist, self.on_cmd)
        self.timer = rospy.Timer(rospy.Duration(self.dt), self.step)

    def on_cmd(self, msg):
        self.cmd = msg

    def step(self, _event):
        self.yaw += self.cmd.angular.z * self.dt
        self.x += self.cmd.linear.x * math.cos(self.yaw) * self.dt
        self.y += self.cmd.linear.x * math.sin(self.yaw) * self.dt
        odom = Odometry()
        odom.header.stamp = rospy.Time.now()
        odom.header.frame_id = self.frame_id
        odom.child_frame_id = 'base_link'
        odom.pose.pose.position.x = self.x
        odom.pose.pose.position.y = self.y
        odom.pose.pose.orientation.z = math.sin(self.yaw / 2.0)
        odom.pose.pose.orientation.w = math.cos(self.yaw / 2.0)
        odom.twist.twist = self.cmd
        self.pub.publish(odom)


if __name__ == '__main__':
    rospy.init_node('unicycle_sim')
    UnicycleSim()
    rospy.spin()
