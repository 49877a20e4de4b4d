#!/usr/bin/env python3
"""Row planner: a straight path down the current orchard row, twice a second."""
import rospy
from geometry_msgs.msg import PoseStamped
from nav_msgs.msg import Path


def main():
    rospy.init_node('row_planner')
    pub = rospy.Publisher('row_plan', Path, queue_size=1)
    rate = rospy.Rate(2.0)
    while not rospy.is_shutdown():
        path = Path()
        path.header.frame_id = 'map'
        for i in range(10):
            pose = PoseStamped()
            pose.pose.position.x = float(i)
            path.poses.append(pose)
        pub.publish(path)
        rate.sleep()


if __name__ == '__main__':
    main()
