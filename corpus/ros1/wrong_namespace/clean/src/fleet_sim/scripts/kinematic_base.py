#!/usr/bin/env python3
"""Point-mass base that echoes commanded velocity as odometry."""
import math

import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry

pose = [0.0, 0.0, 0.0]
last_cmd = Twist()


def on_cmd(msg):
    global last_cmd
    last_cmd = msg


def tick(event):
    dt = 0.1 if event.last_real is None else (event.current_real - event.last_real).to_sec()
    pose[2] += last_cmd.angular.z * dt
    pose[0] += last_cmd.linear.x * math.cos(pose[2]) * dt
    pose[1] += last_cmd.linear.x * math.sin(pose[2]) * dt
    odom = Odometry()
    odom.header.stamp = rospy.Time.now()
    odom.header.frame_id = rospy.get_param('~odom_frame', 'odom')
    odom.pose.pose.position.x, odom.pose.pose.position.y = pose[0], pose[1]
    odom.pose.pose.orientation.z = math.sin(pose[2] / 2)
    odom.pose.pose.orientation.w = math.cos(pose[2] / 2)
    odom.twist.twist = last_cmd
    odom_pub.publish(odom)


if __name__ == '__main__':
    rospy.init_node('base')
    odom_pub = rospy.Publisher('odom', Odometry, queue_size=10)
    rospy.Subscriber('cmd_vel', Twist, on_cmd)
    rospy.Timer(rospy.Duration(0.1), tick)
    rospy.spin()
