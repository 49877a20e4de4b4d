#!/usr/bin/env python3
"""Safety supervisor: checks the emergency stop chain once at start-up and enables the base."""
import rospy
from std_msgs.msg import Bool


def main():
    rospy.init_node('safety_supervisor')
    chain_ok = rospy.get_param('~estop_chain_ok', True)
    enable_pub = rospy.Publisher('base_enabled', Bool, queue_size=1, latch=True)
    enable_pub.publish(Bool(data=chain_ok))
    rospy.spin()


if __name__ == '__main__':
    main()
