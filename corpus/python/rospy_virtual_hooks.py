#!/usr/bin/env python3
"""Behavior: a template-method base class. The base registers the timer and calls hooks that a
subclass overrides: the override's guard (a pose received) holds the output back; a thread
subclass publishes from its run() loop."""
import threading

import rospy
from geometry_msgs.msg import PoseStamped
from std_msgs.msg import Float64, String


class Reporter(object):

    def __init__(self, period):
        self.report_pub = rospy.Publisher("report", String, queue_size=1)
        rospy.Timer(rospy.Duration(period), self.tick)

    def has_data(self):
        return True

    def describe(self):
        return "idle"

    def tick(self, _event):
        if not self.has_data():
            return
        self.report_pub.publish(String(data=self.describe()))


class PoseReporter(Reporter):

    def __init__(self):
        self.pose = None
        rospy.Subscriber("pose", PoseStamped, self.on_pose)
        super(PoseReporter, self).__init__(1.0)

    def on_pose(self, msg):
        self.pose = msg

    def has_data(self):
        return self.pose is not None

    def describe(self):
        return "x=%.2f" % self.pose.pose.position.x


class Ticker(threading.Thread):

    def __init__(self, hz):
        super(Ticker, self).__init__()
        self.hz = hz
        self.stopped = False
        self.tick_pub = rospy.Publisher("ticks", Float64, queue_size=1)

    def run(self):
        rate = rospy.Rate(self.hz)
        while not self.stopped:
            self.tick_pub.publish(Float64(data=rospy.get_time()))
            rate.sleep()


if __name__ == "__main__":
    rospy.init_node("reporter")
    PoseReporter()
    Ticker(4).start()
    rospy.spin()
