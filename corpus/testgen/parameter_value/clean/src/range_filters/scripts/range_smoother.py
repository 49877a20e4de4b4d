#!/usr/bin/env python3
"""Moving-average smoother of a range reading over ~window samples."""
import collections

import rospy
from std_msgs.msg import Float64


def main():
    rospy.init_node("range_smoother")
    window = rospy.get_param("~window", 4)
    window = max(window, 1)
    samples = collections.deque(maxlen=max(window, 1))
    pub = rospy.Publisher("range_smoothed", Float64, queue_size=10)
    rospy.Subscriber("range_raw", Float64, lambda msg: samples.append(msg.data), queue_size=10)
    rate = rospy.Rate(20)
    while not rospy.is_shutdown():
        pub.publish(Float64(sum(samples) / window))
        rate.sleep()


if __name__ == "__main__":
    main()
