#!/usr/bin/env python3
# tf2_ros.Buffer serves ~tf2_frames unless it is built with debug=False (tf2_tools' echo.py): the
# buffer of this node does, the quiet one does not.
import rospy
import tf2_ros


def main():
    rospy.init_node("frame_echo")
    buffer = tf2_ros.Buffer(cache_time=rospy.Duration(10.0))
    quiet = tf2_ros.Buffer(debug=False)
    tf2_ros.TransformListener(buffer)
    rospy.spin()


if __name__ == "__main__":
    main()
