#!/usr/bin/env python3
"""Publishes a latched rectangular waypoint path for the follower."""
import rospy
from geometry_msgs.msg import PoseStamped
from nav_msgs.msg import Path


def build_path(length, width, spacing, frame_id):
    corners = [(0.0, 0.0), (length, 0.0), (length, width), (0.0, width), (0.0, 0.0)]
    path = Path()
    path.header.frame_id = frame_id
    path.header.stamp = rospy.Time.now()
    for (x0, y0), (x1, y1) in zip(corners, corners[1:]):
        steps = max(1, int(max(abs(x1 - x0), abs(y1 - y0)) / spacing))
        for i in range(steps):
            pose = PoseStamped()
            pose.header.frame_id = frame_id
            pose.pose.position.x = x0 + (x1 - x0) * i / steps
            pose.pose.position.y = y0 + (y1 - y0) * i / steps
            pose.pose.orientation.w = 1.0
            path.poses.append(pose)
    return path


if __name__ == '__main__':
    rospy.init_node('waypoint_loader')
    pub = rospy.Publisher('base_waypoints', Path, queue_size=1, latch=True)
    path = build_path(rospy.get_param('~length', 6.0), rospy.get_param('~width', 3.0),
                      rospy.get_param('~spacing', 0.5), rospy.get_param('~frame_id', 'odom'))
    pub.publish(path)
    rospy.loginfo('published %d waypoints', len(path.poses))
    rospy.spin()
