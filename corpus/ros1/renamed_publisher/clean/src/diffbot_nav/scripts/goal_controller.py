#!/usr/bin/env python3
"""Proportional go-to-goal controller driven by odometry feedback."""
import math

import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry


class GoalController(object):
    def __init__(self):
        self.goal = (rospy.get_param('~goal_x', 1.0), rospy.get_param('~goal_y', 0.0))
        self.k_lin = rospy.get_param('~k_linear', 0.5)
        self.k_ang = rospy.get_param('~k_angular', 1.5)
        self.cmd_pub = rospy.Publisher('cmd_vel', Twist, queue_size=10)
        self.odom_sub = rospy.Subscriber('odom', Odometry, self.on_odom)

    def on_odom(self, msg):
        p = msg.pose.pose.position
        q = msg.pose.pose.orientation
        yaw = 2.0 * math.atan2(q.z, q.w)
        dx, dy = self.goal[0] - p.x, self.goal[1] - p.y
        dist = math.hypot(dx, dy)
        cmd = Twist()
        if dist > 0.05:
            err = math.atan2(dy, dx) - yaw
            err = math.atan2(math.sin(err), math.cos(err))
            cmd.angular.z = self.k_ang * err
            cmd.linear.x = min(self.k_lin * dist, 0.4) * max(0.0, math.cos(err))
        self.cmd_pub.publish(cmd)


if __name__ == '__main__':
    rospy.init_node('goal_controller')
    GoalController()
    rospy.spin()
