#!/usr/bin/env python3
"""Operator dashboard: collects the base and safety status, checks the map service periodically."""
import rospy
import std_msgs.msg
from nav_msgs.msg import OccupancyGrid
from nav_msgs.srv import GetMap

BASE_NODE = 'base_sim'
GATE_NODE = 'safety_gate'
MAP_SERVICE = '/static_map'


class Dashboard(object):
    def __init__(self):
        self.status = {'base': 'unknown', 'gate': 'unknown'}
        self.map_info = None
        rospy.Subscriber('%s/status' % BASE_NODE, std_msgs.msg.String, self.on_status, callback_args='base')
        rospy.Subscriber('{}/state'.format(GATE_NODE), std_msgs.msg.String, self.on_status, callback_args='gate')
        rospy.Subscriber('/map', OccupancyGrid, self.on_map, queue_size=1)
        rospy.wait_for_service(MAP_SERVICE)
        self.get_map = rospy.ServiceProxy(MAP_SERVICE, GetMap)
        self.timer = rospy.Timer(rospy.Duration(rospy.get_param('~period', 2.0)), self.report)

    def on_status(self, msg, source):
        self.status[source] = msg.data

    def on_map(self, msg):
        self.map_info = msg.info

    def report(self, _event):
        try:
            served = self.get_map().map.info
            rospy.loginfo('base %s, gate %s, map %dx%d', self.status['base'], self.status['gate'],
                          served.width, served.height)
        except rospy.ServiceException as exc:
            rospy.logwarn('map service failed: %s', exc)


if __name__ == '__main__':
    rospy.init_node('dashboard')
    Dashboard()
    rospy.spin()
