#!/usr/bin/env python3
"""Kinematic bicycle model driving a constant curve; publishes odometry."""
import math

import rospy
from nav_msgs.msg import Odometry


def main():
    rospy.init_node('vehicle_sim')
    frame = rospy.get_param('~frame_id', 'odom')
    odom_pub = rospy.Publisher('odom', Odometry, queue_size=10)
    hz = 20.0
    rate = rospy.Rate(hz)
    x = y = yaw = 0.0
    while not rospy.is_shutdown():
        x += 1.0 / hz * math.cos(yaw)
        y += 1.0 / hz * math.sin(yaw)
        yaw += 0.05 / hz
        odom = Odometry()
        odom.header.stamp = rospy.Time.now()
        odom.header.frame_id = frame
        odom.pose.pose.position.x = x
        odom.pose.pose.position.y = y
        odom.pose.pose.orientation.z = math.sin(yaw / 2.0)
        odom.pose.pose.orientation.w = math.cos(yaw / 2.0)
        odom_pub.publish(odom)
        rate.sleep()


if __name__ == '__main__':
    try:
        main()
    except rospy.ROSInterruptException:
        pass
