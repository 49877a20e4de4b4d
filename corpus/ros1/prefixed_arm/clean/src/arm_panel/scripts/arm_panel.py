#!/usr/bin/env python3
"""The operator's panel: shows the left arm's status, reports the gripper and the wrist, and
listens to the commands the driver sends to the shoulder and the elbow."""
import rospy
from std_msgs.msg import Float64, String


def show(msg):
    rospy.loginfo_throttle(5.0, str(msg.data))


if __name__ == "__main__":
    rospy.init_node("arm_panel")
    rospy.Subscriber("/left/arm/status", String, show)
    states = [rospy.Publisher(joint + "/state", Float64, queue_size=1) for joint in ("gripper", "wrist")]
    commands = [rospy.Subscriber(joint + "/command", Float64, show) for joint in ("shoulder", "elbow")]
    rate = rospy.Rate(2.0)
    while not rospy.is_shutdown():
        for state in states:
            state.publish(Float64(data=0.5))
        rate.sleep()
