#!/usr/bin/env python3
"""Fuses filtered laser and sonar ranges into a nearest-obstacle estimate."""
import rospy
from sensor_msgs.msg import LaserScan, Range

latest = {'laser': float('inf'), 'front': float('inf'), 'rear': float('inf')}


def on_scan(scan):
    finite = [r for r in scan.ranges if r < float('inf')]
    latest['laser'] = min(finite) if finite else float('inf')


def make_sonar_cb(key):
    def cb(msg):
        latest[key] = msg.range if msg.min_range <= msg.range <= msg.max_range else float('inf')
    return cb


def report(_event):
    source = min(latest, key=latest.get)
    rospy.loginfo('nearest obstacle %.2f m (%s)', latest[source], source)


if __name__ == '__main__':
    rospy.init_node('obstacle_fusion')
    rospy.Subscriber('scan_filtered', LaserScan, on_scan)
    rospy.Subscriber('sonar/front', Range, make_sonar_cb('front'))
    rospy.Subscriber('sonar/rear', Range, make_sonar_cb('rear'))
    rospy.Timer(rospy.Duration(rospy.get_param('~report_period', 1.0)), report)
    rospy.spin()
