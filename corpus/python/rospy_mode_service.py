#!/usr/bin/env python3
"""Behavior: a mode switch served by services; the controller commands the base only in auto
mode and once armed (module constants name the modes)."""
import rospy
from geometry_msgs.msg import Twist
from std_msgs.msg import String
from std_srvs.srv import SetBool, SetBoolResponse, Trigger, TriggerResponse

AUTO = "auto"
MANUAL = "manual"


class ModeController(object):
    SPEED = 0.4

    def __init__(self):
        self.mode = MANUAL
        self.armed = False
        self.cmd_pub = rospy.Publisher("cmd_vel", Twist, queue_size=1)
        self.mode_pub = rospy.Publisher("~mode", String, queue_size=1, latch=True)
        rospy.Service("~set_auto", SetBool, self.on_set_auto)
        rospy.Service("~arm", Trigger, self.on_arm)
        rospy.Timer(rospy.Duration(0.05), self.control)

    def on_set_auto(self, req):
        self.mode = AUTO if req.data else MANUAL
        self.mode_pub.publish(String(data=self.mode))
        return SetBoolResponse(success=True, message=self.mode)

    def on_arm(self, _req):
        self.armed = True
        return TriggerResponse(success=True, message="armed")

    def control(self, _event):
        if self.mode != AUTO or not self.armed:
            return
        command = Twist()
        command.linear.x = self.SPEED
        self.cmd_pub.publish(command)


if __name__ == "__main__":
    rospy.init_node("mode_controller")
    ModeController()
    rospy.spin()
