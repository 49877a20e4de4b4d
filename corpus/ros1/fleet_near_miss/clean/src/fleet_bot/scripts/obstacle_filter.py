#!/usr/bin/env python3
"""Reports the nearest obstacle ahead at 10 Hz, from the latest lidar scan (none yet: infinitely far)."""
import rospy
from geometry_msgs.msg import PointStamped
from sensor_msgs.msg import LaserScan


class ObstacleFilter:
    def __init__(self):
        self.nearest = float('inf')
        self.pub = rospy.Publisher('obstacles', PointStamped, queue_size=5)
        rospy.Subscriber('scan', LaserScan, self.on_scan)
        rospy.Timer(rospy.Duration(0.1), self.on_timer)

    def on_scan(self, scan):
        self.nearest = min(scan.ranges)

    def on_timer(self, _event):
        msg = PointStamped()
        msg.header.stamp = rospy.Time.now()
        msg.point.x = self.nearest
        self.pub.publish(msg)


if __name__ == '__main__':
    rospy.init_node('obstacle_filter')
    ObstacleFilter()
    rospy.spin()
