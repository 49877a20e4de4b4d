#!/usr/bin/env python3
"""Aggregates proximity reports and logs a periodic fleet summary."""
import rospy
from std_msgs.msg import Float32


class Dashboard(object):
    def __init__(self):
        self.samples = []
        rospy.Subscriber('fleet/min_range', Float32, self.on_range)
        period = rospy.get_param('~summary_period', 5.0)
        rospy.Timer(rospy.Duration(period), self.summarize)

    def on_range(self, msg):
        self.samples.append(msg.data)

    def summarize(self, _event):
        if not self.samples:
            rospy.loginfo('no proximity reports received yet')
            return
        rospy.loginfo('closest approach %.2f m over %d reports',
                      min(self.samples), len(self.samples))
        self.samples = []


if __name__ == '__main__':
    rospy.init_node('fleet_dashboard')
    Dashboard()
    rospy.spin()
