#!/usr/bin/env python3
"""Simulated motor driver: turns velocity commands into wheel joint states."""
import rospy
from geometry_msgs.msg import Twist
from sensor_msgs.msg import JointState


class MotorDriver(object):
    def __init__(self):
        self.radius = rospy.get_param('~wheel_radius', 0.05)
        self.separation = rospy.get_param('~wheel_separation', 0.30)
        self.cmd = Twist()
        self.left = 0.0
        self.right = 0.0
        self.pub = rospy.Publisher('joint_states', JointState, queue_size=10)
        rospy.Subscriber('cmd_vel', Twist, self.on_cmd)
        self.last = rospy.Time.now()
        rospy.Timer(rospy.Duration(0.05), self.step)

    def on_cmd(self, msg):
        self.cmd = msg

    def step(self, _event):
        now = rospy.Time.now()
        dt = (now - self.last).to_sec()
        self.last = now
        v, w = self.cmd.linear.x, self.cmd.angular.z
        self.left += (v - w * self.separation / 2.0) / self.radius * dt
        self.right += (v + w * self.separation / 2.0) / self.radius * dt
        js = JointState()
        js.header.stamp = now
        js.name = ['left_wheel_joint', 'right_wheel_joint']
        js.position = [self.left, self.right]
        self.pub.publish(js)


if __name__ == '__main__':
    rospy.init_node('motor_driver')
    MotorDriver()
    rospy.spin()
