#!/usr/bin/env python3
"""Publishes a synthetic mono8 image whose intensity follows the exposure setting."""
import rospy
from sensor_msgs.msg import CameraInfo, Image
from std_msgs.msg import Float64

exposure = {'value': 0.5}


def exposure_cb(msg):
    exposure['value'] = max(0.0, min(1.0, msg.data))


def main():
    rospy.init_node('camera_driver')
    width = rospy.get_param('~width', 64)
    height = rospy.get_param('~height', 48)
    frame_id = rospy.get_param('~frame_id', 'camera_optical_frame')
    image_pub = rospy.Publisher('image', Image, queue_size=5)
    info_pub = rospy.Publisher('camera_info', CameraInfo, queue_size=5)
    rospy.Subscriber('exposure', Float64, exposure_cb)
    rate = rospy.Rate(rospy.get_param('~fps', 15.0))
    while not rospy.is_shutdown():
        img = Image()
        img.header.stamp = rospy.Time.now()
        img.header.frame_id = frame_id
        img.width, img.height = width, height
        img.encoding = 'mono8'
        img.step = width
        img.data = bytes([int(255 * exposure['value'])]) * (width * height)
        info = CameraInfo(header=img.header, width=width, height=height)
        image_pub.publish(img)
        info_pub.publish(info)
        rate.sleep()


if __name__ == '__main__':
    try:
        main()
    except rospy.ROSInterruptException:
        rospy.loginfo("interrupted, shutting down")
