#!/usr/bin/env python3
"""Fleet bridge: forwards what the fleet server sends for this robot, under the robot's host name.
The message type is the one the fleet server announces (argv[1])."""
import socket
import sys

import roslib.message
import rospy


def main():
    rospy.init_node('fleet_bridge')
    message_class = roslib.message.get_message_class(sys.argv[1])
    topic = '/' + socket.gethostname() + '/cmd_vel'
    pub = rospy.Publisher(topic, message_class, queue_size=1)
    rospy.spin()
    pub.unregister()


if __name__ == '__main__':
    main()
