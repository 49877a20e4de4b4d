#!/usr/bin/env python3
"""Collision monitor: raises the safety stop whenever a tracked obstacle is inside the stop zone."""
import math

import rospy
from geometry_msgs.msg import PoseArray
from std_msgs.msg import Bool


def main():
    rospy.init_node('collision_monitor')
    stop_radius = rospy.get_param('~stop_radius', 0.6)
    stop_pub = rospy.Publisher('safety_stop', Bool, queue_size=1)

    def on_obstacles(msg):
        near = any(math.hypot(p.position.x, p.position.y) < stop_radius for p in msg.poses)
        stop_pub.publish(Bool(data=near))

    rospy.Subscriber('obstacles', PoseArray, on_obstacles, queue_size=1)
    rospy.spin()


if __name__ == '__main__':
    main()
