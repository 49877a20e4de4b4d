#!/usr/bin/env python3
"""Emulated 2D laser scanner that reports a circular room around the robot."""
import math

import rospy
from sensor_msgs.msg import LaserScan


def main():
    rospy.init_node('laser_driver')
    frame_id = rospy.get_param('~frame_id', 'laser')
    room_radius = rospy.get_param('~room_radius', 3.0)
    beams = rospy.get_param('~beams', 360)
    pub = rospy.Publisher('scan', LaserScan, queue_size=10)
    rate = rospy.Rate(rospy.get_param('~scan_rate', 10.0))
    while not rospy.is_shutdown():
        scan = LaserScan()
        scan.header.stamp = rospy.Time.now()
        scan.header.frame_id = frame_id
        scan.angle_min = -math.pi
        scan.angle_max = math.pi
        scan.angle_increment = 2.0 * math.pi / beams
        scan.range_min = 0.05
        scan.range_max = 10.0
        scan.ranges = [room_radius] * beams
        pub.publish(scan)
        rate.sleep()


if __name__ == '__main__':
    try:
        main()
    except rospy.ROSInterruptException:
        rospy.loginfo("interrupted, shutting down")
