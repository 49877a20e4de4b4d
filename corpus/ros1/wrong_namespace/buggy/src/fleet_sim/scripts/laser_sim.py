#!/usr/bin/env python3
"""Fake front-facing laser: a wall at a slowly varying distance."""
import math

import rospy
from sensor_msgs.msg import LaserScan

if __name__ == '__main__':
    rospy.init_node('laser')
    frame = rospy.get_param('~frame_id', 'laser')
    fov = math.radians(rospy.get_param('~fov_deg', 180.0))
    n = 181
    scan_pub = rospy.Publisher('scan', LaserScan, queue_size=5)
    rate = rospy.Rate(rospy.get_param('~rate', 8.0))
    while not rospy.is_shutdown():
        t = rospy.Time.now()
        wall = 1.5 + math.sin(t.to_sec() * 0.2)
        msg = LaserScan(angle_min=-fov / 2, angle_max=fov / 2,
                        angle_increment=fov / (n - 1), range_min=0.1, range_max=8.0)
        msg.header.stamp, msg.header.frame_id = t, frame
        msg.ranges = [min(8.0, wall / max(0.05, math.cos(msg.angle_min + i * msg.angle_increment)))
                      for i in range(n)]
        scan_pub.publish(msg)
        try:
            rate.sleep()
        except rospy.ROSInterruptException:
            break
