#!/usr/bin/env python3
"""Behavior: a heartbeat loop that starts beating once the driver reports ready (a module flag set
in a callback through `global`); the loop rate is a parameter's default."""
import rospy
from std_msgs.msg import Bool, Empty

driver_ready = False


def on_status(msg):
    global driver_ready
    if msg.data:
        driver_ready = True


def main():
    rospy.init_node("heartbeat")
    beat = rospy.Publisher("heartbeat", Empty, queue_size=1)
    alive = rospy.Publisher("alive", Bool, queue_size=1)
    rospy.Subscriber("driver/ready", Bool, on_status)
    rate = rospy.Rate(rospy.get_param("~rate", 20))
    while not rospy.is_shutdown():
        alive.publish(Bool(data=driver_ready))
        if not driver_ready:
            rate.sleep()
            continue
        beat.publish(Empty())
        rate.sleep()


if __name__ == "__main__":
    main()
