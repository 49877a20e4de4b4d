#!/usr/bin/env python3
"""The gripper: publishes its opening on gripper/joint_state."""
import rospy
from std_msgs.msg import Float64

if __name__ == "__main__":
    rospy.init_node("gripper_driver")
    state = rospy.Publisher("gripper/joint_state", Float64, queue_size=1)
    rate = rospy.Rate(2.0)
    while not rospy.is_shutdown():
        state.publish(Float64(data=0.02))
        rate.sleep()
