#!/usr/bin/env python3
"""Drives the arm's joints: one command topic per controller of ~controllers (a list of
{name, joint}), the gripper's and the wrist's state as inputs, and a status topic under the
optional ~robot_prefix."""
import rospy
from std_msgs.msg import Float64, String


class ArmDriver(object):

    def __init__(self):
        try:
            self.prefix = rospy.get_param("~robot_prefix")
        except KeyError:
            self.prefix = ""
        if self.prefix != "":
            self.prefix = "/" + self.prefix
        self.status = rospy.Publisher(self.prefix + "/arm/status", String, queue_size=1)
        self.commands = {}
        for controller in rospy.get_param("~controllers"):
            topic = controller["name"] + "/command"
            self.commands[controller["joint"]] = rospy.Publisher(topic, Float64, queue_size=1)
        self.listen("gripper")
        self.listen("wrist")

    def listen(self, joint):
        rospy.Subscriber(joint + "/state", Float64, self.on_state, callback_args=joint)

    def on_state(self, msg, joint):
        self.status.publish(String(data="%s at %.2f" % (joint, msg.data)))


if __name__ == "__main__":
    rospy.init_node("arm_driver")
    ArmDriver()
    rospy.spin()
