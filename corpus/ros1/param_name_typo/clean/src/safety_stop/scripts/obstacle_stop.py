#!/usr/bin/env python3
"""Publishes a stop command when the scan of ~scan_topic sees anything nearer than ~stop_distance."""
import rospy
from geometry_msgs.msg import Twist
from sensor_msgs.msg import LaserScan


class ObstacleStop(object):
    def __init__(self):
        self.stop_distance = rospy.get_param('~stop_distance', 0.4)
        scan_topic = rospy.get_param('~scan_topic', 'scan')
        self.stop_pub = rospy.Publisher('stop_cmd', Twist, queue_size=1)
        rospy.Subscriber(scan_topic, LaserScan, self.on_scan, queue_size=1)

    def on_scan(self, scan):
        if any(r < self.stop_distance for r in scan.ranges):
            self.stop_pub.publish(Twist())


if __name__ == '__main__':
    rospy.init_node('obstacle_stop')
    ObstacleStop()
    rospy.spin()
