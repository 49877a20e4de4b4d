#!/usr/bin/env python3
"""Heartbeat relay: republishes the count of in-order heartbeats at 10 Hz."""
import rospy
from std_msgs.msg import UInt32


class Relay:
    def __init__(self):
        self.expected = None
        self.count = 0
        self.pub = rospy.Publisher("relay_status", UInt32, queue_size=10)
        rospy.Subscriber("heartbeat", UInt32, self.on_beat, queue_size=10)

    def on_beat(self, msg):

        self.expected = msg.data + 1
        self.count += 1


def main():
    rospy.init_node("heartbeat_relay")
    relay = Relay()
    rate = rospy.Rate(10)
    while not rospy.is_shutdown():

        relay.pub.publish(UInt32(relay.count))
        rate.sleep()


if __name__ == "__main__":
    main()
