#!/usr/bin/env python3
"""Drops laser returns outside a configurable range window."""
import rospy
from sensor_msgs.msg import LaserScan


class ScanFilter(object):
    def __init__(self):
        self.lower = rospy.get_param('~min_range', 0.1)
        self.upper = rospy.get_param('~max_range', 10.0)
        self.pub = rospy.Publisher('scan_filtered', LaserScan, queue_size=5)
        self.sub = rospy.Subscriber('scan', LaserScan, self.on_scan, queue_size=1)

    def on_scan(self, scan):
        out = LaserScan()
        out.header = scan.header
        out.angle_min, out.angle_max = scan.angle_min, scan.angle_max
        out.angle_increment = scan.angle_increment
        out.range_min = max(scan.range_min, self.lower)
        out.range_max = min(scan.range_max, self.upper)
        out.ranges = [r if out.range_min <= r <= out.range_max else float('inf')
                      for r in scan.ranges]
        self.pub.publish(out)


if __name__ == '__main__':
    rospy.init_node('scan_filter')
    ScanFilter()
    rospy.spin()
