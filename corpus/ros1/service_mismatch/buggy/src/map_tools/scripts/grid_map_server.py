#!/usr/bin/env python3
"""Builds an empty walled occupancy grid and serves it on 'map' and 'static_map'."""
import rospy
from nav_msgs.msg import OccupancyGrid
from nav_msgs.srv import GetMap, GetMapResponse


def make_grid(width, height, resolution, frame_id):
    grid = OccupancyGrid()
    grid.header.frame_id = frame_id
    grid.header.stamp = rospy.Time.now()
    grid.info.resolution = resolution
    grid.info.width = width
    grid.info.height = height
    grid.info.origin.orientation.w = 1.0
    cells = []
    for row in range(height):
        for col in range(width):
            border = row in (0, height - 1) or col in (0, width - 1)
            cells.append(100 if border else 0)
    grid.data = cells
    return grid


if __name__ == '__main__':
    rospy.init_node('map_server')
    grid = make_grid(rospy.get_param('~width', 80), rospy.get_param('~height', 60),
                     rospy.get_param('~resolution', 0.05), rospy.get_param('~frame_id', 'map'))
    map_pub = rospy.Publisher('map', OccupancyGrid, queue_size=1, latch=True)
    map_pub.publish(grid)
    rospy.Service('static_map', GetMap, lambda req: GetMapResponse(map=grid))
    rospy.loginfo('serving %dx%d map', grid.info.width, grid.info.height)
    rospy.spin()
