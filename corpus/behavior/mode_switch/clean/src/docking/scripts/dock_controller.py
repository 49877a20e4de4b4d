#!/usr/bin/env python3
"""Dock controller: idle until a mission switches it on with ~start; once active, steers towards
the detected dock at 10 Hz. Every mode change is announced on ~mode."""
import rospy
from geometry_msgs.msg import PoseStamped, Twist
from roscpp.srv import Empty, EmptyResponse
from std_msgs.msg import String


class DockController(object):
    def __init__(self):
        self.gain = rospy.get_param('~gain', 0.8)
        self.active = False
        self.dock_pose = None
        self.cmd_pub = rospy.Publisher('cmd_vel', Twist, queue_size=1)
        self.mode_pub = rospy.Publisher('~mode', String, queue_size=1)
        rospy.Subscriber('dock_pose', PoseStamped, self.on_dock_pose, queue_size=1)
        rospy.Service('~start', Empty, self.on_start)
        rospy.Service('~stop', Empty, self.on_stop)
        rospy.Timer(rospy.Duration(0.1), self.control)

    def on_dock_pose(self, msg):
        self.dock_pose = msg

    def on_start(self, _req):
        self.active = True
        self.mode_pub.publish(String(data='docking'))
        return EmptyResponse()

    def on_stop(self, _req):
        self.active = False
        self.mode_pub.publish(String(data='idle'))
        return EmptyResponse()

    def control(self, _event):
        if not self.active or self.dock_pose is None:
            return
        cmd = Twist()
        cmd.linear.x = self.gain * self.dock_pose.pose.position.x
        cmd.angular.z = self.gain * self.dock_pose.pose.position.y
        self.cmd_pub.publish(cmd)


if __name__ == '__main__':
    rospy.init_node('dock_controller')
    DockController()
    rospy.spin()
