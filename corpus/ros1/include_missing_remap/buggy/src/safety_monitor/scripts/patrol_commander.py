#!/usr/bin/env python3
"""Issues a slow circular patrol velocity command."""
import rospy
from geometry_msgs.msg import Twist

if __name__ == '__main__':
    rospy.init_node('patrol_commander')
    speed = rospy.get_param('~speed', 0.2)
    turn_rate = rospy.get_param('~turn_rate', 0.3)
    pub = rospy.Publisher('cmd_vel', Twist, queue_size=10)
    rate = rospy.Rate(10)
    while not rospy.is_shutdown():
        cmd = Twist()
        cmd.linear.x = speed
        cmd.angular.z = turn_rate
        pub.publish(cmd)
        try:
            rate.sleep()
        except rospy.ROSInterruptException:
            break
