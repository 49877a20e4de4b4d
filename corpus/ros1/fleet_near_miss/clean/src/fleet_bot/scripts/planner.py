#!/usr/bin/env python3
"""Slows the robot down when an obstacle is near."""
import rospy
from geometry_msgs.msg import PointStamped, Twist


class Planner:
    def __init__(self):
        self.cmd = rospy.Publisher('cmd_vel', Twist, queue_size=1)
        rospy.Subscriber('obstacles', PointStamped, self.on_obstacle)

    def on_obstacle(self, obstacle):
        twist = Twist()
        twist.linear.x = 0.5 if obstacle.point.x > 1.0 else 0.0
        self.cmd.publish(twist)


if __name__ == '__main__':
    rospy.init_node('planner')
    Planner()
    rospy.spin()
