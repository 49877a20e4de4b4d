#!/usr/bin/env python3
"""The operator's panel: shows the gripper's state from the topic ~state_topic names."""
import rospy
from std_msgs.msg import Float64


class Panel(object):

    def __init__(self):
        topic = rospy.get_param("~state_topic", "joint_state")
        rospy.Subscriber(topic, Float64, self.on_state)

    def on_state(self, msg):
        rospy.loginfo_throttle(5.0, "gripper opening: %.3f m" % msg.data)


if __name__ == "__main__":
    rospy.init_node("gripper_panel")
    Panel()
    rospy.spin()
