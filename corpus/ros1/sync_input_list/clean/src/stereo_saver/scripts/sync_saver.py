#!/usr/bin/env python3
"""Saves synchronised frames of the image topics listed in ~inputs (one topic alone is accepted
too), and reports each save on ~saved."""
import message_filters
import rospy
from sensor_msgs.msg import Image
from std_msgs.msg import String


class SyncSaver(object):

    def __init__(self):
        topics = rospy.get_param("~inputs")
        if not isinstance(topics, list):
            topics = [topics]
        subs = [message_filters.Subscriber(topic, Image) for topic in topics]
        self.sync = message_filters.TimeSynchronizer(subs, 10)
        self.sync.registerCallback(self.save)
        self.saved = rospy.Publisher("~saved", String, queue_size=1)

    def save(self, *images):
        self.saved.publish(String(data="%d images" % len(images)))


if __name__ == "__main__":
    rospy.init_node("sync_saver")
    SyncSaver()
    rospy.spin()
