#!/usr/bin/env python3
"""Back-and-forth patrol along the x axis between two limits."""
import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry


class Patrol(object):
    def __init__(self):
        self.x_min = rospy.get_param('~x_min', 0.0)
        self.x_max = rospy.get_param('~x_max', 4.0)
        self.speed = rospy.get_param('~speed', 0.3)
        self.direction = 1.0
        self.cmd_pub = rospy.Publisher('cmd_vel', Twist, queue_size=1)
        rospy.Subscriber('odom', Odometry, self.on_odom, queue_size=1)

    def on_odom(self, odom):
        x = odom.pose.pose.position.x
        if x > self.x_max:
            self.direction = -1.0
        elif x < self.x_min:
            self.direction = 1.0
        cmd = Twist()
        cmd.linear.x = self.direction * self.speed
        self.cmd_pub.publish(cmd)


if __name__ == '__main__':
    rospy.init_node('patrol')
    Patrol()
    rospy.spin()
