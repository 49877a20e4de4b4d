#!/usr/bin/env python3
"""Waypoint source: streams the waypoints of a rectangular field route at 5 Hz."""
import rospy
from geometry_msgs.msg import PoseStamped

CORNERS = [(0.0, 0.0), (20.0, 0.0), (20.0, 6.0), (0.0, 6.0)]


def main():
    rospy.init_node('waypoint_source')
    frame = rospy.get_param('~frame_id', 'field')
    pub = rospy.Publisher('route_waypoints', PoseStamped, queue_size=10)
    rate = rospy.Rate(5)
    index = 0
    while not rospy.is_shutdown():
        x, y = CORNERS[index % len(CORNERS)]
        waypoint = PoseStamped()
        waypoint.header.stamp = rospy.Time.now()
        waypoint.header.frame_id = frame
        waypoint.pose.position.x = x
        waypoint.pose.position.y = y
        waypoint.pose.orientation.w = 1.0
        pub.publish(waypoint)
        index += 1
        rate.sleep()


if __name__ == '__main__':
    try:
        main()
    except rospy.ROSInterruptException:
        pass
