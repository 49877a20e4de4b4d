#!/usr/bin/env python3
"""Curvature monitor: announces itself, blocks until the first pose, then reports the heading
change per metre driven at 2 Hz."""
import math

import rospy
from geometry_msgs.msg import PoseStamped
from std_msgs.msg import Float64, String


def yaw_of(pose):
    q = pose.pose.orientation
    return 2.0 * math.atan2(q.z, q.w)


def main():
    rospy.init_node('curvature_monitor')
    state_pub = rospy.Publisher('~state', String, queue_size=1, latch=True)
    curvature_pub = rospy.Publisher('curvature', Float64, queue_size=1)
    state_pub.publish(String(data='waiting for odom_pose'))
    last = rospy.wait_for_message('odom_pose', PoseStamped)
    latest = [last]
    rospy.Subscriber('odom_pose', PoseStamped, lambda msg: latest.__setitem__(0, msg), queue_size=1)
    rate = rospy.Rate(2)
    while not rospy.is_shutdown():
        pose = latest[0]
        step = math.hypot(pose.pose.position.x - last.pose.position.x, pose.pose.position.y - last.pose.position.y)
        turn = yaw_of(pose) - yaw_of(last)
        curvature_pub.publish(Float64(data=turn / step if step > 1e-3 else 0.0))
        last = pose
        rate.sleep()


if __name__ == '__main__':
    try:
        main()
    except rospy.ROSInterruptException:
        pass
