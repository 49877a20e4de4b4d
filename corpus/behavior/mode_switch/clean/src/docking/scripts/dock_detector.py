#!/usr/bin/env python3
"""Dock detector stand-in: the dock seen 1.2 m ahead, slightly to the left, at 10 Hz."""
import rospy
from geometry_msgs.msg import PoseStamped


def main():
    rospy.init_node('dock_detector')
    frame = rospy.get_param('~frame_id', 'base_link')
    pub = rospy.Publisher('dock_pose', PoseStamped, queue_size=1)
    rate = rospy.Rate(10)
    while not rospy.is_shutdown():
        pose = PoseStamped()
        pose.header.stamp = rospy.Time.now()
        pose.header.frame_id = frame
        pose.pose.position.x = 1.2
        pose.pose.position.y = 0.1
        pose.pose.orientation.w = 1.0
        pub.publish(pose)
        rate.sleep()


if __name__ == '__main__':
    try:
        main()
    except rospy.ROSInterruptException:
        pass
