#!/usr/bin/env python3
"""Attitude filter: the drone's attitude from every IMU measurement."""
import rospy
from geometry_msgs.msg import QuaternionStamped
from sensor_msgs.msg import Imu


class AttitudeFilter(object):
    def __init__(self):
        self.attitude_pub = rospy.Publisher('attitude', QuaternionStamped, queue_size=10)
        rospy.Subscriber('imu/dat', Imu, self.on_imu, queue_size=50)

    def on_imu(self, reading):
        attitude = QuaternionStamped()
        attitude.header = reading.header
        attitude.quaternion = reading.orientation
        self.attitude_pub.publish(attitude)


if __name__ == '__main__':
    rospy.init_node('attitude_filter')
    AttitudeFilter()
    rospy.spin()
