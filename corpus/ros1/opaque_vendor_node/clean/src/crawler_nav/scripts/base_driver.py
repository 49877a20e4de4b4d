#!/usr/bin/env python3
"""Track drive of the crawler: wheel odometry at 20 Hz (simulated)."""
import rospy
from nav_msgs.msg import Odometry


def main():
    rospy.init_node('base_driver')
    pub = rospy.Publisher('odom', Odometry, queue_size=10)
    rate = rospy.Rate(20.0)
    while not rospy.is_shutdown():
        odom = Odometry()
        odom.header.stamp = rospy.Time.now()
        odom.header.frame_id = 'odom'
        pub.publish(odom)
        rate.sleep()


if __name__ == '__main__':
    main()
