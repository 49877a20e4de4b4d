#!/usr/bin/env python3
"""Reports the closest laser return of one robot to the fleet dashboard."""
import math

import rospy
from sensor_msgs.msg import LaserScan
from std_msgs.msg import Float32


def main():
    rospy.init_node('scan_monitor')
    warn_range = rospy.get_param('~warn_range', 0.5)
    report_pub = rospy.Publisher('/fleet/min_range', Float32, queue_size=10)

    def on_scan(scan):
        finite = [r for r in scan.ranges if not math.isinf(r) and not math.isnan(r)]
        if not finite:
            return
        closest = min(finite)
        if closest < warn_range:
            rospy.logwarn_throttle(1.0, 'obstacle at %.2f m', closest)
        report_pub.publish(Float32(closest))

    rospy.Subscriber('scan', LaserScan, on_scan, queue_size=1)
    rospy.spin()


if __name__ == '__main__':
    main()
