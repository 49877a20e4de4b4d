#!/usr/bin/env python3
"""Obstacle monitor: raises a flag for every scan with a return closer than the stop distance."""
import rospy
from sensor_msgs.msg import LaserScan
from std_msgs.msg import Bool


class ObstacleMonitor(object):
    def __init__(self):
        self.stop_distance = rospy.get_param('~stop_distance', 0.4)
        self.flag_pub = rospy.Publisher('obstacle', Bool, queue_size=1)
        rospy.Subscriber('front_scan', LaserScan, self.on_scan, queue_size=1)

    def on_scan(self, scan):
        near = any(scan.range_min < r < self.stop_distance for r in scan.ranges)
        self.flag_pub.publish(Bool(data=near))


if __name__ == '__main__':
    rospy.init_node('obstacle_monitor')
    ObstacleMonitor()
    rospy.spin()
