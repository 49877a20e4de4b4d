#!/usr/bin/env python3
"""Serves a static occupancy grid of the patrol area over nav_msgs/GetMap and a latched topic."""
import rospy
from nav_msgs.msg import OccupancyGrid
from nav_msgs.srv import GetMap, GetMapResponse


class MapServer(object):
    SERVICE = 'static_map'
    MAP_TOPIC = 'map'

    def __init__(self, resolution, cells):
        self.grid = self.empty_room(resolution, cells)
        self.pub = rospy.Publisher(MapServer.MAP_TOPIC, OccupancyGrid, queue_size=1, latch=True)
        self.srv = rospy.Service(self.SERVICE, GetMap, self.handle)
        self.pub.publish(self.grid)

    @staticmethod
    def empty_room(resolution, cells):
        grid = OccupancyGrid()
        grid.header.stamp = rospy.Time.now()
        grid.header.frame_id = 'map'
        grid.info.resolution = resolution
        grid.info.width = grid.info.height = cells
        grid.info.origin.position.x = grid.info.origin.position.y = -cells * resolution / 2.0
        grid.info.origin.orientation.w = 1.0
        border = {0, cells - 1}
        grid.data = [100 if r in border or c in border else 0 for r in range(cells) for c in range(cells)]
        return grid

    def handle(self, _request):
        return GetMapResponse(map=self.grid)


if __name__ == '__main__':
    rospy.init_node('map_server')
    MapServer(rospy.get_param('~resolution', 0.1), rospy.get_param('~cells', 80))
    rospy.spin()
