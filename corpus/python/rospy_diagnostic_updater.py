#!/usr/bin/env python3
"""A monitor that reports through diagnostic_updater: the Updater publishes /diagnostics."""
import rospy
from diagnostic_msgs.msg import DiagnosticStatus
from diagnostic_updater import DiagnosticTask, Updater


class LoadTask(DiagnosticTask):
    def __init__(self):
        DiagnosticTask.__init__(self, 'load')

    def run(self, stat):
        stat.summary(DiagnosticStatus.OK, 'fine')
        return stat


def main():
    rospy.init_node('load_monitor')
    updater = Updater()
    updater.setHardwareID('host')
    updater.add(LoadTask())
    rate = rospy.Rate(1)
    while not rospy.is_shutdown():
        updater.update()
        rate.sleep()


if __name__ == '__main__':
    main()
