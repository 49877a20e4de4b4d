#!/usr/bin/env python
"""Box publisher written for Python 2, its indentation mixing tabs and spaces."""
import rospy
from std_msgs.msg import String


def on_box(msg):
    print "box", msg.data


def main():
    rospy.init_node("box_publisher")
    pub = rospy.Publisher("boxes", String, queue_size=1)
    if True:
	rospy.Subscriber("detections", String, on_box)
    rate = rospy.Rate(10)
    while not rospy.is_shutdown():
        pub.publish(String(data="box"))
	rate.sleep()


main()
