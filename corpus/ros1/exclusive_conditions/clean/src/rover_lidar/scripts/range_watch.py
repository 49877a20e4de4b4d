#!/usr/bin/env python3
"""Warns when an obstacle is closer than ~min_range (the simulator's copy warns louder)."""
import rospy
from sensor_msgs.msg import LaserScan


def main():
    rospy.init_node('range_watch')
    min_range = rospy.get_param('~min_range', 0.5)

    def heard(scan):
        if scan.ranges and min(scan.ranges) < min_range:
            rospy.logwarn('obstacle closer than %.2f m', min_range)

    rospy.Subscriber('scan', LaserScan, heard, queue_size=1)
    rospy.spin()


if __name__ == '__main__':
    main()
