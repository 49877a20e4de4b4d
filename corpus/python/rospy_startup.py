#!/usr/bin/env python3
"""Behavior: publishes at start-up: a latched map from module code, an initial pose after a busy
wait for the first clock message, a stop command on shutdown, and a publish nothing calls."""
import rospy
from geometry_msgs.msg import PoseWithCovarianceStamped, Twist
from nav_msgs.msg import OccupancyGrid
from rosgraph_msgs.msg import Clock

clock_seen = None


def on_clock(msg):
    global clock_seen
    clock_seen = msg.clock


def blank_map(width, height):
    grid = OccupancyGrid()
    grid.info.width, grid.info.height = width, height
    grid.data = [0] * (width * height)
    return grid


def stop(pub):
    pub.publish(Twist())


def debug_dump(pub):
    pub.publish(blank_map(1, 1))


if __name__ == "__main__":
    rospy.init_node("map_loader")
    map_pub = rospy.Publisher("map", OccupancyGrid, queue_size=1, latch=True)
    map_pub.publish(blank_map(rospy.get_param("~width", 100), rospy.get_param("~height", 100)))
    rospy.Subscriber("clock", Clock, on_clock)
    while clock_seen is None and not rospy.is_shutdown():
        rospy.sleep(0.1)
    pose_pub = rospy.Publisher("initialpose", PoseWithCovarianceStamped, queue_size=1, latch=True)
    pose_pub.publish(PoseWithCovarianceStamped())
    cmd_pub = rospy.Publisher("cmd_vel", Twist, queue_size=1)
    rospy.on_shutdown(lambda: stop(cmd_pub))
    rospy.spin()
