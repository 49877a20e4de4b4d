#!/usr/bin/env python3
"""Simulated planar lidar in a corridor with one box ahead."""
import math

import rospy
from sensor_msgs.msg import LaserScan


def corridor_range(angle, half_width=1.5, box_x=2.0):
    c, s = math.cos(angle), math.sin(angle)
    ranges = [half_width / abs(s)] if abs(s) > 1e-6 else []
    if c > 1e-6 and abs(box_x * s / c) < 0.3:
        ranges.append(box_x / c)
    return min(ranges) if ranges else 30.0


def main():
    rospy.init_node('lidar_sim')
    frame = rospy.get_param('~frame_id', 'laser')
    pub = rospy.Publisher('scan', LaserScan, queue_size=1)
    count = 181
    rate = rospy.Rate(10)
    while not rospy.is_shutdown():
        scan = LaserScan()
        scan.header.stamp = rospy.Time.now()
        scan.header.frame_id = frame
        scan.angle_min = -math.pi / 2
        scan.angle_max = math.pi / 2
        scan.angle_increment = math.pi / (count - 1)
        scan.range_min = 0.05
        scan.range_max = 30.0
        scan.ranges = [corridor_range(scan.angle_min + i * scan.angle_increment) for i in range(count)]
        pub.publish(scan)
        rate.sleep()


if __name__ == '__main__':
    try:
        main()
    except rospy.ROSInterruptException:
        pass
