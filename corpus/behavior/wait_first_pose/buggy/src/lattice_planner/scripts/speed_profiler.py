#!/usr/bin/env python3
"""Speed profiler: the target speed for the current pose, slowing down near the end of the lane."""
import math

import rospy
from geometry_msgs.msg import PoseStamped
from std_msgs.msg import Float64


class SpeedProfiler(object):
    def __init__(self):
        self.max_speed = rospy.get_param('~max_speed', 2.5)
        self.lane_end_x = rospy.get_param('~lane_end_x', 40.0)
        self.pose = None
        self.speed_pub = rospy.Publisher('speed_profile', Float64, queue_size=1)
        rospy.Subscriber('odom_pose', PoseStamped, self.on_pose, queue_size=1)

    def on_pose(self, msg):
        self.pose = msg

    def target_speed(self):
        remaining = max(0.0, self.lane_end_x - self.pose.pose.position.x)
        return min(self.max_speed, math.sqrt(2.0 * 0.5 * remaining))

    def spin(self):
        rate = rospy.Rate(5)
        while not rospy.is_shutdown():
            if self.pose is not None:
                self.speed_pub.publish(Float64(data=self.target_speed()))
            rate.sleep()


if __name__ == '__main__':
    rospy.init_node('speed_profiler')
    try:
        SpeedProfiler().spin()
    except rospy.ROSInterruptException:
        pass
