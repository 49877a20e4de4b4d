#!/usr/bin/env python3
"""Wheel driver: applies each velocity command and reports the odometry it results in."""
import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry


class BaseDriver(object):
    def __init__(self):
        self.odom_pub = rospy.Publisher('odom', Odometry, queue_size=10)
        rospy.Subscriber('cmd_vel', Twist, self.on_command, queue_size=1)
        self.x = 0.0

    def on_command(self, twist):
        self.x += twist.linear.x * 0.1
        odom = Odometry()
        odom.header.stamp = rospy.Time.now()
        odom.header.frame_id = 'odom'
        odom.pose.pose.position.x = self.x
        self.odom_pub.publish(odom)


if __name__ == '__main__':
    rospy.init_node('base_driver')
    BaseDriver()
    rospy.spin()
