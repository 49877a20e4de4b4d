#!/usr/bin/env python3
"""actionlib, tf2 broadcasters and listeners, message_filters, timers, wait_for_message."""
import actionlib
import message_filters
import rospy
import tf2_ros
from move_base_msgs.msg import MoveBaseAction
from control_msgs.msg import FollowJointTrajectoryAction
from sensor_msgs.msg import CameraInfo, Image


def on_pair(image, info):
    rospy.logdebug("image %dx%d with its camera info", image.width, image.height)


def main():
    rospy.init_node("coordinator")
    client = actionlib.SimpleActionClient("move_base", MoveBaseAction)
    server = actionlib.SimpleActionServer("~follow", FollowJointTrajectoryAction, auto_start=False)
    broadcaster = tf2_ros.TransformBroadcaster()
    static = tf2_ros.StaticTransformBroadcaster()
    buffer = tf2_ros.Buffer()
    listener = tf2_ros.TransformListener(buffer)
    image = message_filters.Subscriber("camera/image_raw", Image)
    info = message_filters.Subscriber("camera/camera_info", CameraInfo)
    sync = message_filters.TimeSynchronizer([image, info], 10)
    first = rospy.wait_for_message("camera/camera_info", CameraInfo, timeout=5)
    rospy.Timer(rospy.Duration(0.5), lambda event: None)
    rospy.spin()


main()
