#!/usr/bin/env python3
"""Route monitor: a periodic monitor (alive signal on every tick) specialised to report the
length of the current grid plan once one has been received."""
import math

import rospy
from nav_msgs.msg import Path
from std_msgs.msg import Empty, Float32


class PeriodicMonitor(object):
    def __init__(self, period):
        self.alive_pub = rospy.Publisher('~alive', Empty, queue_size=1)
        rospy.Timer(rospy.Duration(period), self._tick)

    def is_ready(self):
        return True

    def report(self):
        raise NotImplementedError

    def _tick(self, _event):
        self.alive_pub.publish(Empty())
        if self.is_ready():
            self.report()


class RouteMonitor(PeriodicMonitor):
    def __init__(self):
        self.plan = None
        self.length_pub = rospy.Publisher('route_length', Float32, queue_size=1)
        rospy.Subscriber('grid_plan', Path, self.on_plan, queue_size=1)
        super(RouteMonitor, self).__init__(0.5)

    def on_plan(self, msg):
        self.plan = msg

    def is_ready(self):
        return self.plan is not None

    def report(self):
        poses = [p.pose.position for p in self.plan.poses]
        length = sum(math.hypot(b.x - a.x, b.y - a.y) for a, b in zip(poses, poses[1:]))
        self.length_pub.publish(Float32(data=length))


if __name__ == '__main__':
    rospy.init_node('route_monitor')
    RouteMonitor()
    rospy.spin()
