#!/usr/bin/env python3
"""Behavior: timer-driven outputs: a module-level timer callback with a global publisher, a
lambda timer, a one-shot timer through functools.partial, and a tf broadcaster on a timer."""
import functools

import rospy
import tf2_ros
from geometry_msgs.msg import TransformStamped
from std_msgs.msg import Float32, String

status_pub = None


def report(_event):
    status_pub.publish(String(data="ok"))


def announce(pub, text, _event):
    pub.publish(String(data=text))


class Odometer(object):

    def __init__(self):
        self.distance = 0.0
        self.distance_pub = rospy.Publisher("distance", Float32, queue_size=1)
        self.broadcaster = tf2_ros.TransformBroadcaster()
        rospy.Timer(rospy.Duration(1.0), lambda event: self.distance_pub.publish(Float32(data=self.distance)))
        rospy.Timer(rospy.Duration(0.02), self.broadcast)

    def broadcast(self, event):
        transform = TransformStamped()
        transform.header.stamp = event.current_real
        transform.header.frame_id = "odom"
        transform.child_frame_id = "base_link"
        self.broadcaster.sendTransform(transform)


def main():
    global status_pub
    rospy.init_node("odometer")
    status_pub = rospy.Publisher("status", String, queue_size=1)
    hello = rospy.Publisher("hello", String, queue_size=1, latch=True)
    rospy.Timer(rospy.Duration(2.0), report)
    rospy.Timer(rospy.Duration(0.5), functools.partial(announce, hello, "odometer up"), oneshot=True)
    Odometer()
    rospy.spin()


if __name__ == "__main__":
    main()
