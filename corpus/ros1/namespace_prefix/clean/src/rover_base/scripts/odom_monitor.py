#!/usr/bin/env python3
"""Odometry monitor: reports the distance driven for every odometry message."""
import rospy
from nav_msgs.msg import Odometry
from std_msgs.msg import Float64


class OdomMonitor(object):
    def __init__(self):
        self.distance_pub = rospy.Publisher('distance', Float64, queue_size=1)
        rospy.Subscriber('odom', Odometry, self.on_odom, queue_size=1)

    def on_odom(self, odom):
        self.distance_pub.publish(Float64(data=abs(odom.pose.pose.position.x)))


if __name__ == '__main__':
    rospy.init_node('odom_monitor')
    OdomMonitor()
    rospy.spin()
