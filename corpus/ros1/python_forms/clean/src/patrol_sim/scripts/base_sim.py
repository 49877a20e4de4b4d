#!/usr/bin/env python3
"""Differential-drive base simulator: integrates cmd_vel into odometry and reports its state."""
import math

import rospy
import std_msgs.msg
from geometry_msgs import msg as gm
from nav_msgs.msg import Odometry

CMD_TOPIC = 'cmd_vel'
ODOM_TOPIC = 'odom'
STATUS_TOPIC = '~status'
CMD_TIMEOUT = 0.5


class BaseSim(object):
    def __init__(self):
        self.x = self.y = self.yaw = 0.0
        self.cmd = gm.Twist()
        self.last_cmd = rospy.Time(0)
        self.dt = 1.0 / rospy.get_param('~rate', 20.0)
        self.odom_frame = rospy.get_param('~odom_frame', 'odom')
        self.odom_pub = rospy.Publisher(ODOM_TOPIC, Odometry, queue_size=10)
        self.status_pub = rospy.Publisher(STATUS_TOPIC, std_msgs.msg.String, queue_size=1)
        self.cmd_sub = rospy.Subscriber(CMD_TOPIC, gm.Twist, self.on_cmd, queue_size=1)
        self.step_timer = rospy.Timer(rospy.Duration(self.dt), self.step)
        self.status_timer = rospy.Timer(rospy.Duration(1.0), self.report)

    def on_cmd(self, msg):
        self.cmd = msg
        self.last_cmd = rospy.Time.now()

    def step(self, _event):
        if (rospy.Time.now() - self.last_cmd).to_sec() > CMD_TIMEOUT:
            self.cmd = gm.Twist()
        self.yaw += self.cmd.angular.z * self.dt
        self.x += self.cmd.linear.x * math.cos(self.yaw) * self.dt
        self.y += self.cmd.linear.x * math.sin(self.yaw) * self.dt
        odom = Odometry()
        odom.header.stamp = rospy.Time.now()
        odom.header.frame_id = self.odom_frame
        odom.child_frame_id = 'base_link'
        odom.pose.pose.position.x = self.x
        odom.pose.pose.position.y = self.y
        odom.pose.pose.orientation.z = math.sin(self.yaw / 2.0)
        odom.pose.pose.orientation.w = math.cos(self.yaw / 2.0)
        odom.twist.twist = self.cmd
        self.odom_pub.publish(odom)

    def report(self, _event):
        moving = abs(self.cmd.linear.x) > 1e-3 or abs(self.cmd.angular.z) > 1e-3
        self.status_pub.publish(std_msgs.msg.String(data='moving' if moving else 'idle'))


if __name__ == '__main__':
    rospy.init_node('base_sim')
    BaseSim()
    rospy.spin()
