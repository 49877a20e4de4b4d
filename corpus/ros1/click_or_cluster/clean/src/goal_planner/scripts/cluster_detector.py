#!/usr/bin/env python3
"""Obstacle cluster detector: the centre of the nearest cluster, twice a second (simulated)."""
import rospy
from geometry_msgs.msg import PointStamped


def main():
    rospy.init_node('cluster_detector')
    pub = rospy.Publisher('cloud_clusters', PointStamped, queue_size=1)
    rate = rospy.Rate(2.0)
    while not rospy.is_shutdown():
        centre = PointStamped()
        centre.header.stamp = rospy.Time.now()
        centre.header.frame_id = 'map'
        centre.point.x = 4.0
        pub.publish(centre)
        rate.sleep()


if __name__ == '__main__':
    main()
