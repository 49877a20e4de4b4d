#!/usr/bin/env python3
"""Dock localizer: the dock's pose, once either a GPS fix or a reading of the dock's ultrasonic
beacon has located the robot. The beacon is optional hardware; either input is enough."""
import rospy
from geometry_msgs.msg import PoseStamped
from sensor_msgs.msg import NavSatFix, Range


class DockLocalizer(object):
    def __init__(self):
        self.located = False
        self.distance = 0.0
        self.pose_pub = rospy.Publisher('dock_pose', PoseStamped, queue_size=1)
        rospy.Subscriber('gps/fix', NavSatFix, self.on_fix, queue_size=1)
        rospy.Subscriber('beacon/range', Range, self.on_beacon, queue_size=1)
        rospy.Timer(rospy.Duration(0.5), self.publish_pose)

    def on_fix(self, fix):
        self.distance = abs(fix.latitude - 52.0) * 111000.0
        self.located = True

    def on_beacon(self, reading):
        self.distance = reading.range
        self.located = True

    def publish_pose(self, _event):
        if not self.located:
            return
        pose = PoseStamped()
        pose.header.stamp = rospy.Time.now()
        pose.header.frame_id = 'base_link'
        pose.pose.position.x = self.distance
        self.pose_pub.publish(pose)


if __name__ == '__main__':
    rospy.init_node('dock_localizer')
    DockLocalizer()
    rospy.spin()
