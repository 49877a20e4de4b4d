#!/usr/bin/env python3
"""Integrates wheel encoder positions into a planar odometry estimate."""
import math

import rospy
from nav_msgs.msg import Odometry
from sensor_msgs.msg import JointState

radius = 0.05
separation = 0.30
state = {'x': 0.0, 'y': 0.0, 'th': 0.0, 'prev': None}
odom_pub = None


def joints_cb(msg):
    if len(msg.position) < 2:
        return
    if state['prev'] is None:
        state['prev'] = list(msg.position[:2])
        return
    dl = (msg.position[0] - state['prev'][0]) * radius
    dr = (msg.position[1] - state['prev'][1]) * radius
    state['prev'] = list(msg.position[:2])
    state['th'] += (dr - dl) / separation
    state['x'] += (dl + dr) / 2.0 * math.cos(state['th'])
    state['y'] += (dl + dr) / 2.0 * math.sin(state['th'])
    odom = Odometry()
    odom.header.stamp = msg.header.stamp
    odom.header.frame_id = rospy.get_param('~odom_frame', 'odom')
    odom.child_frame_id = 'base_link'
    odom.pose.pose.position.x = state['x']
    odom.pose.pose.position.y = state['y']
    odom.pose.pose.orientation.z = math.sin(state['th'] / 2.0)
    odom.pose.pose.orientation.w = math.cos(state['th'] / 2.0)
    odom_pub.publish(odom)


if __name__ == '__main__':
    rospy.init_node('wheel_odometry')
    radius = rospy.get_param('~wheel_radius', radius)
    separation = rospy.get_param('~wheel_separation', separation)
    odom_pub = rospy.Publisher('odom', Odometry, queue_size=10)
    rospy.Subscriber('joint_states', JointState, joints_cb)
    rospy.spin()
