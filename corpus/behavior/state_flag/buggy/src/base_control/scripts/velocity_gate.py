#!/usr/bin/env python3
"""Velocity gate: passes teleoperation commands to the base once the base has been enabled."""
import rospy
from geometry_msgs.msg import Twist
from std_msgs.msg import Bool, String


class VelocityGate(object):
    def __init__(self):
        self.max_speed = rospy.get_param('~max_speed', 1.0)
        self.enabled = False
        self.cmd_pub = rospy.Publisher('cmd_vel', Twist, queue_size=1)
        self.warn_pub = rospy.Publisher('~warning', String, queue_size=1)
        rospy.Subscriber('base_enable', Bool, self.on_enable, queue_size=1)
        rospy.Subscriber('teleop/cmd_vel', Twist, self.on_command, queue_size=1)
        rospy.Timer(rospy.Duration(1.0), self.warn_while_disabled)

    def on_enable(self, msg):
        self.enabled = msg.data

    def warn_while_disabled(self, _event):
        if self.enabled:
            return
        self.warn_pub.publish(String(data='commands dropped: base not enabled'))

    def on_command(self, msg):
        if not self.enabled:
            return
        msg.linear.x = max(-self.max_speed, min(self.max_speed, msg.linear.x))
        self.cmd_pub.publish(msg)


if __name__ == '__main__':
    rospy.init_node('velocity_gate')
    VelocityGate()
    rospy.spin()
