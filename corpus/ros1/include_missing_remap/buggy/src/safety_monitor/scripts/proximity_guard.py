#!/usr/bin/env python3
"""Raises an emergency stop when any laser return is closer than a threshold."""
import math

import rospy
from sensor_msgs.msg import LaserScan
from std_msgs.msg import Bool


class ProximityGuard(object):
    def __init__(self):
        self.stop_distance = rospy.get_param('~stop_distance', 0.35)
        self.estop_pub = rospy.Publisher('estop', Bool, queue_size=1, latch=True)
        self.scan_sub = rospy.Subscriber('scan', LaserScan, self.on_scan)
        self.stopped = None

    def on_scan(self, scan):
        valid = [r for r in scan.ranges
                 if not math.isnan(r) and scan.range_min <= r <= scan.range_max]
        closest = min(valid) if valid else float('inf')
        stopped = closest < self.stop_distance
        if stopped != self.stopped:
            rospy.loginfo('estop %s (closest %.2f m)', 'ON' if stopped else 'OFF', closest)
            self.stopped = stopped
            self.estop_pub.publish(Bool(stopped))


if __name__ == '__main__':
    rospy.init_node('proximity_guard')
    ProximityGuard()
    rospy.spin()
