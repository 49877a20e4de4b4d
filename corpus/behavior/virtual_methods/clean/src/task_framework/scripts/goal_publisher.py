#!/usr/bin/env python3
"""Goal publisher: sends the mission's goal once a second, as an operator's goal tool would."""
import rospy
from geometry_msgs.msg import PoseStamped


def main():
    rospy.init_node('goal_publisher')
    pub = rospy.Publisher('goal', PoseStamped, queue_size=1)
    rate = rospy.Rate(rospy.get_param('~rate', 1.0))
    while not rospy.is_shutdown():
        goal = PoseStamped()
        goal.header.frame_id = rospy.get_param('~frame_id', 'map')
        goal.header.stamp = rospy.Time.now()
        goal.pose.position.x = rospy.get_param('~x', 3.0)
        goal.pose.position.y = rospy.get_param('~y', 1.5)
        goal.pose.orientation.w = 1.0
        pub.publish(goal)
        rate.sleep()


if __name__ == '__main__':
    try:
        main()
    except rospy.ROSInterruptException:
        pass
