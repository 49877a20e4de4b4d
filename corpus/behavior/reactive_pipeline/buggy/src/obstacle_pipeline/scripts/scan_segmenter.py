#!/usr/bin/env python3
"""Scan segmenter: turns every laser scan into the Cartesian points of its valid returns."""
import math

import rospy
from geometry_msgs.msg import Point32
from sensor_msgs.msg import LaserScan, PointCloud


def to_points(scan, max_range):
    points = []
    for i, r in enumerate(scan.ranges):
        if not (scan.range_min <= r <= min(scan.range_max, max_range)):
            continue
        angle = scan.angle_min + i * scan.angle_increment
        points.append(Point32(x=r * math.cos(angle), y=r * math.sin(angle), z=0.0))
    return points


class ScanSegmenter(object):
    def __init__(self):
        self.max_range = rospy.get_param('~max_range', 8.0)
        self.points_pub = rospy.Publisher('scan_points', PointCloud, queue_size=1)
        rospy.Subscriber('scan', LaserScan, self.on_scan, queue_size=1)

    def on_scan(self, scan):
        cloud = PointCloud()
        cloud.header = scan.header
        cloud.points = to_points(scan, self.max_range)
        self.points_pub.publish(cloud)


if __name__ == '__main__':
    rospy.init_node('scan_segmenter')
    ScanSegmenter()
    rospy.spin()
