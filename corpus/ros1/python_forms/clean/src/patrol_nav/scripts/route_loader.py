#!/usr/bin/env python3
"""Loads the patrol route from the parameter server and publishes it once, latched."""
import rospy
from geometry_msgs.msg import PoseStamped
from nav_msgs.msg import Path

ROUTE_NS = 'route'
DEFAULT_ROUTE = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]]


def build_path(points, frame_id):
    path = Path()
    path.header.stamp = rospy.Time.now()
    path.header.frame_id = frame_id
    for x, y in points:
        pose = PoseStamped()
        pose.header = path.header
        pose.pose.position.x, pose.pose.position.y = float(x), float(y)
        pose.pose.orientation.w = 1.0
        path.poses.append(pose)
    return path


def main():
    rospy.init_node('route_loader')
    frame_id = rospy.get_param('~frame_id', 'odom')
    points = rospy.get_param('~waypoints', DEFAULT_ROUTE)
    pub = rospy.Publisher('%s/patrol_route' % ROUTE_NS, Path, queue_size=1, latch=True)
    pub.publish(build_path(points, frame_id))
    rospy.loginfo('published a patrol route of %d waypoints', len(points))
    rospy.spin()


if __name__ == '__main__':
    main()
