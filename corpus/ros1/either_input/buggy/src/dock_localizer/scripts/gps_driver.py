#!/usr/bin/env python3
"""GPS receiver driver: one fix per second (simulated)."""
import rospy
from sensor_msgs.msg import NavSatFix


def main():
    rospy.init_node('gps_driver')
    pub = rospy.Publisher('fix', NavSatFix, queue_size=5)
    rate = rospy.Rate(1.0)
    while not rospy.is_shutdown():
        fix = NavSatFix()
        fix.header.stamp = rospy.Time.now()
        fix.latitude, fix.longitude = 52.0, 5.0
        pub.publish(fix)
        rate.sleep()


if __name__ == '__main__':
    main()
