#!/usr/bin/env python3
"""Detects obstacles and publishes them as markers (version 2: was a PoseArray on 'obstacle')."""
import rospy
from visualization_msgs.msg import Marker, MarkerArray

if __name__ == '__main__':
    rospy.init_node('obstacle_detector')
    pub = rospy.Publisher('obstacles', MarkerArray, queue_size=1)
    rate = rospy.Rate(5.0)
    while not rospy.is_shutdown():
        pub.publish(MarkerArray(markers=[Marker(type=Marker.CYLINDER)]))
        rate.sleep()
