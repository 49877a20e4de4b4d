#!/usr/bin/env python3
"""Publishes a filtered planar scan (a ring of constant ranges) at 10 Hz."""
import rospy
from sensor_msgs.msg import LaserScan


def main():
    rospy.init_node('fake_lidar')
    pub = rospy.Publisher('scan_filtered', LaserScan, queue_size=5)
    rate = rospy.Rate(10)
    while not rospy.is_shutdown():
        scan = LaserScan()
        scan.header.stamp = rospy.Time.now()
        scan.header.frame_id = 'laser'
        scan.angle_min, scan.angle_max, scan.angle_increment = -1.57, 1.57, 0.0175
        scan.range_min, scan.range_max = 0.1, 10.0
        scan.ranges = [4.0] * 180
        pub.publish(scan)
        rate.sleep()


if __name__ == '__main__':
    main()
