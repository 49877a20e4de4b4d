#!/usr/bin/env python3
"""Stops the base when the IMU reports a tilt."""
import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from sensor_msgs.msg import Imu

rospy.init_node("tilt_guard")
stop = rospy.Publisher("cmd_vel", Twist, queue_size=1)
rospy.Subscriber("imu/data", Imu, lambda msg: stop.publish(Twist()) if abs(msg.linear_acceleration.x) > 5 else None)
rospy.Subscriber("odom", Odometry, lambda msg: None)
rospy.spin()
