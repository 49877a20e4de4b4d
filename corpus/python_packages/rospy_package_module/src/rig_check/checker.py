"""The rig checker: synchronises a mono and a stereo camera's images with their camera_info."""
import message_filters
import rospy
import sensor_msgs.msg
from std_msgs.msg import String


class CheckerNode:

    def __init__(self, slop):
        mono = rospy.resolve_name("monocular")
        pairs = [(mono + "/image_rect", sensor_msgs.msg.Image), (mono + "/camera_info", sensor_msgs.msg.CameraInfo)]
        self.mono = [message_filters.Subscriber(topic, kind) for (topic, kind) in pairs]
        self.stereo = []
        for side in ("left", "right"):
            for leaf, kind in (("image_rect", sensor_msgs.msg.Image), ("camera_info", sensor_msgs.msg.CameraInfo)):
                self.stereo.append(message_filters.Subscriber("stereo/%s/%s" % (side, leaf), kind))
        self.report = rospy.Publisher(rospy.get_namespace() + "rig_report", String, queue_size=1)


class UnusedNode:

    def __init__(self):
        rospy.Publisher("never_started", String, queue_size=1)
