"""A teleop that picks its command message by distribution: two conditional imports bind one name,
so the publisher's type is one of them, not silently the last."""
import os

import rclpy

if os.environ.get('ROS_DISTRO') == 'humble':
    from geometry_msgs.msg import Twist as CmdVel
else:
    from geometry_msgs.msg import TwistStamped as CmdVel


def main():
    rclpy.init()
    node = rclpy.create_node('teleop')
    pub = node.create_publisher(CmdVel, 'cmd_vel', 10)
    pub.publish(CmdVel())


if __name__ == '__main__':
    main()
