#!/usr/bin/env python3
"""Range filter: drops the returns of the mower's own deck from every scan."""
import rospy
from sensor_msgs.msg import LaserScan


class RangeFilter(object):
    def __init__(self):
        self.pub = rospy.Publisher('scan_filtered', LaserScan, queue_size=5)
        rospy.Subscriber('scan', LaserScan, self.on_scan, queue_size=5)

    def on_scan(self, scan):
        scan.ranges = [r if r > 0.3 else float('inf') for r in scan.ranges]
        self.pub.publish(scan)


if __name__ == '__main__':
    rospy.init_node('range_filter')
    RangeFilter()
    rospy.spin()
