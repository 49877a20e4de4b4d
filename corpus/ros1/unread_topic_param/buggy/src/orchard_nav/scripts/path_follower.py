#!/usr/bin/env python3
"""Path follower: steers towards the first pose of the path it follows (~plan_topic)."""
import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Path


class PathFollower(object):
    def __init__(self):
        self.speed = rospy.get_param('~speed', 0.8)
        plan_topic = rospy.get_param('~plan_topic', 'row_plan')
        self.cmd_pub = rospy.Publisher('cmd_vel', Twist, queue_size=1)
        rospy.Subscriber(plan_topic, Path, self.on_path, queue_size=1)

    def on_path(self, path):
        cmd = Twist()
        if path.poses:
            cmd.linear.x = self.speed
            cmd.angular.z = 0.5 * path.poses[0].pose.position.y
        self.cmd_pub.publish(cmd)


if __name__ == '__main__':
    rospy.init_node('path_follower')
    PathFollower()
    rospy.spin()
