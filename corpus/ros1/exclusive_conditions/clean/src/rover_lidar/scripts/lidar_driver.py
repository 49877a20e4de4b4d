#!/usr/bin/env python3
"""Driver of the rover's lidar (either model; ~range_max tells them apart): one scan every 0.1 s (simulated)."""
import rospy
from sensor_msgs.msg import LaserScan


def main():
    rospy.init_node('lidar_driver')
    range_max = rospy.get_param('~range_max', 4.0)
    pub = rospy.Publisher('scan', LaserScan, queue_size=5)
    rate = rospy.Rate(10.0)
    while not rospy.is_shutdown():
        scan = LaserScan()
        scan.header.stamp = rospy.Time.now()
        scan.header.frame_id = 'laser'
        scan.range_max = range_max
        scan.ranges = [range_max / 2] * 360
        pub.publish(scan)
        rate.sleep()


if __name__ == '__main__':
    main()
