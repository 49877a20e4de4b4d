#!/usr/bin/env python3
"""Forwards velocity commands to the motors unless the emergency stop is active."""
import rospy
from geometry_msgs.msg import Twist
from std_msgs.msg import Bool


class BaseController(object):
    def __init__(self):
        self.max_speed = rospy.get_param('~max_speed', 0.5)
        self.estop = False
        rospy.Subscriber('cmd_vel', Twist, self.on_cmd)
        rospy.Subscriber('estop', Bool, self.on_estop)

    def on_estop(self, msg):
        self.estop = msg.data

    def on_cmd(self, cmd):
        if self.estop:
            rospy.logwarn_throttle(2.0, 'estop active, ignoring command')
            return
        v = max(-self.max_speed, min(self.max_speed, cmd.linear.x))
        rospy.logdebug('motor command v=%.2f w=%.2f', v, cmd.angular.z)


if __name__ == '__main__':
    rospy.init_node('base_controller')
    BaseController()
    rospy.spin()
