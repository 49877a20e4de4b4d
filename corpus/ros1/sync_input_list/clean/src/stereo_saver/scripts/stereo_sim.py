#!/usr/bin/env python3
"""A simulated stereo camera: an image and a camera_info topic per side, and a heartbeat in the
camera's namespace."""
import rospy
from sensor_msgs.msg import CameraInfo, Image
from std_msgs.msg import Header

SIDES = ("left", "right")


def main():
    rospy.init_node("stereo_sim")
    images = [rospy.Publisher(side + "/image_raw", Image, queue_size=1) for side in SIDES]
    infos = []
    for side in SIDES:
        infos.append(rospy.Publisher(side + "/camera_info", CameraInfo, queue_size=1))
    beat = rospy.Publisher(rospy.get_namespace() + "heartbeat", Header, queue_size=1)
    rate = rospy.Rate(10)
    while not rospy.is_shutdown():
        stamp = rospy.Time.now()
        for image, info in zip(images, infos):
            image.publish(Image(header=Header(stamp=stamp), height=1, width=1, encoding="mono8", step=1, data=b"\0"))
            info.publish(CameraInfo(header=Header(stamp=stamp), height=1, width=1))
        beat.publish(Header(stamp=stamp))
        rate.sleep()


if __name__ == "__main__":
    main()
