#!/usr/bin/env python3
"""Safety gate: forwards raw velocity commands to the base unless the laser sees an obstacle ahead."""
import math

import rospy
import std_msgs.msg
from geometry_msgs import msg as gm
from sensor_msgs.msg import LaserScan as Scan

RAW_SUFFIX = '_raw'
FRONT_HALF_ANGLE = math.radians(30.0)


def make_state_pub(topic):
    return rospy.Publisher(topic, std_msgs.msg.String, queue_size=1, latch=True)


class SafetyGate(object):
    def __init__(self):
        self.stop_distance = rospy.get_param('~stop_distance', 0.5)
        self.blocked = None
        self.state_pub = make_state_pub('~state')
        self.cmd_pub = rospy.Publisher('cmd_vel', gm.Twist, queue_size=1)
        self.raw_sub = rospy.Subscriber('cmd_vel{}'.format(RAW_SUFFIX), gm.Twist, self.on_cmd, queue_size=1)
        scan_topic = rospy.get_param('~scan_topic', 'base_scan')
        self.scan_sub = rospy.Subscriber(scan_topic, Scan, self.on_scan, queue_size=1)

    def on_scan(self, msg):
        ahead = [r for i, r in enumerate(msg.ranges)
                 if abs(msg.angle_min + i * msg.angle_increment) < FRONT_HALF_ANGLE
                 and msg.range_min < r < msg.range_max]
        blocked = bool(ahead) and min(ahead) < self.stop_distance
        if blocked != self.blocked:
            self.blocked = blocked
            self.state_pub.publish(std_msgs.msg.String(data='blocked' if blocked else 'clear'))

    def on_cmd(self, msg):
        if self.blocked and msg.linear.x > 0.0:
            msg.linear.x = 0.0
        self.cmd_pub.publish(msg)


if __name__ == '__main__':
    rospy.init_node('safety_gate')
    SafetyGate()
    rospy.spin()
