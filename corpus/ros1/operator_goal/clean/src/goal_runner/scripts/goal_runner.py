#!/usr/bin/env python3
"""Turns each goal from RViz's 2D Nav Goal tool into a velocity command."""
import rospy
from geometry_msgs.msg import PoseStamped, Twist


def on_goal(goal):
    command = Twist()
    command.linear.x = 0.2 if goal.pose.position.x > 0 else -0.2
    cmd_pub.publish(command)


rospy.init_node('goal_runner')
cmd_pub = rospy.Publisher('cmd_vel', Twist, queue_size=1)
rospy.Subscriber('move_base_simple/goal', PoseStamped, on_goal)
rospy.spin()
