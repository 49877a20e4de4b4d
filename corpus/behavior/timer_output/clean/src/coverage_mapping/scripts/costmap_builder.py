#!/usr/bin/env python3
"""Costmap builder: inflates the static map around obstacles and republishes it periodically;
reports its own status on a slower timer."""
import rospy
from nav_msgs.msg import OccupancyGrid
from std_msgs.msg import String

LETHAL = 100


class CostmapBuilder(object):
    def __init__(self):
        self.inflation_cells = rospy.get_param('~inflation_cells', 2)
        self.grid = None
        self.costmap_pub = rospy.Publisher('costmap', OccupancyGrid, queue_size=1)
        self.status_pub = rospy.Publisher('~status', String, queue_size=1)
        rospy.Subscriber('map', OccupancyGrid, self.on_map, queue_size=1)
        rospy.Timer(rospy.Duration(0.5), self.publish_costmap)
        rospy.Timer(rospy.Duration(1.0), self.publish_status)

    def on_map(self, msg):
        self.grid = msg

    def inflate(self, grid):
        width = grid.info.width
        cells = list(grid.data)
        out = list(cells)
        for i, value in enumerate(cells):
            if value < LETHAL or width == 0:
                continue
            for d in range(-self.inflation_cells, self.inflation_cells + 1):
                j = i + d
                if 0 <= j < len(out) and j // width == i // width:
                    out[j] = max(out[j], 50)
        costmap = OccupancyGrid()
        costmap.header = grid.header
        costmap.info = grid.info
        costmap.data = out
        return costmap

    def publish_costmap(self, _event):
        if self.grid is None:
            return
        self.costmap_pub.publish(self.inflate(self.grid))

    def publish_status(self, _event):
        self.status_pub.publish(String(data='waiting for map' if self.grid is None else 'ok'))


if __name__ == '__main__':
    rospy.init_node('costmap_builder')
    CostmapBuilder()
    rospy.spin()
