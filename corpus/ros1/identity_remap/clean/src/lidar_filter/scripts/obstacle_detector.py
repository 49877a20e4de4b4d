#!/usr/bin/env python3
"""Obstacle detector: stops the blades when something is close."""
import rospy
from sensor_msgs.msg import LaserScan
from std_msgs.msg import Bool


class ObstacleDetector(object):
    def __init__(self):
        self.stop_pub = rospy.Publisher('blade_stop', Bool, queue_size=1, latch=True)
        self.stop_pub.publish(Bool(data=False))
        rospy.Subscriber('scan_clean', LaserScan, self.on_scan, queue_size=1)

    def on_scan(self, scan):
        if min(scan.ranges) < 0.8:
            self.stop_pub.publish(Bool(data=True))


if __name__ == '__main__':
    rospy.init_node('obstacle_detector')
    ObstacleDetector()
    rospy.spin()
