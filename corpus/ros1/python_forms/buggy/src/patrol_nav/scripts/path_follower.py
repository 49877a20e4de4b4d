#!/usr/bin/env python3
"""Pure-pursuit follower: loops over the patrol route using odometry, emits velocity commands."""
import math

import rospy
from geometry_msgs import msg as gm
from nav_msgs.msg import Odometry, Path

ROUTE_NS = 'route'


class Follower(object):
    CMD_TOPIC = 'cmd_vel'

    def __init__(self, odom_topic, lookahead=0.6):
        self.odom_topic = odom_topic
        self.lookahead = lookahead
        self.speed = rospy.get_param('~speed', 0.3)
        self.route = []
        self.target = 0
        self.pose = None
        self.cmd_pub = rospy.Publisher(self.CMD_TOPIC, gm.Twist, queue_size=1)
        self.route_sub = rospy.Subscriber(f'{ROUTE_NS}/patrol_route', Path, self.on_route, queue_size=1)
        self.odom_sub = rospy.Subscriber(self.odom_topic, Odometry, self.on_odom, queue_size=5)
        self.timer = rospy.Timer(rospy.Duration(0.1), self.control)

    def on_route(self, msg):
        self.route = [(p.pose.position.x, p.pose.position.y) for p in msg.poses]
        self.target = 0

    def on_odom(self, msg):
        q = msg.pose.pose.orientation
        yaw = 2.0 * math.atan2(q.z, q.w)
        self.pose = (msg.pose.pose.position.x, msg.pose.pose.position.y, yaw)

    def control(self, _event):
        cmd = gm.Twist()
        if self.route and self.pose is not None:
            x, y, yaw = self.pose
            gx, gy = self.route[self.target]
            if math.hypot(gx - x, gy - y) < self.lookahead:
                self.target = (self.target + 1) % len(self.route)
                gx, gy = self.route[self.target]
            error = math.atan2(gy - y, gx - x) - yaw
            error = math.atan2(math.sin(error), math.cos(error))
            cmd.linear.x = self.speed * max(0.0, math.cos(error))
            cmd.angular.z = 1.5 * error
        self.cmd_pub.publish(cmd)


if __name__ == '__main__':
    rospy.init_node('path_follower')
    Follower('odom', lookahead=rospy.get_param('~lookahead', 0.6))
    rospy.spin()
