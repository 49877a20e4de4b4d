#!/usr/bin/env python3
"""Mission executive: keeps the docking mission switched on (the controllers treat a repeated
start as a no-op) and reports its progress once a second."""
import rospy
from roscpp.srv import Empty
from std_msgs.msg import String


def call(proxy):
    try:
        proxy()
        return True
    except (rospy.ServiceException, rospy.ROSException):
        return False


def main():
    rospy.init_node('mission_executive')
    start_docking = rospy.ServiceProxy('dock_controller/start', Empty)
    raise_lift = rospy.ServiceProxy('lift/raise', Empty)
    state_pub = rospy.Publisher('mission/state', String, queue_size=1)
    rate = rospy.Rate(1)
    while not rospy.is_shutdown():
        docking = call(start_docking)
        lifting = call(raise_lift)
        state_pub.publish(String(data='docking=%s lifting=%s' % (docking, lifting)))
        rate.sleep()


if __name__ == '__main__':
    try:
        main()
    except rospy.ROSInterruptException:
        pass
