#!/usr/bin/env python3
"""Map loader: a rectangular room with walls, latched once as the static map."""
import rospy
from nav_msgs.msg import OccupancyGrid


def room(width, height, resolution, frame):
    grid = OccupancyGrid()
    grid.header.frame_id = frame
    grid.header.stamp = rospy.Time.now()
    grid.info.width = width
    grid.info.height = height
    grid.info.resolution = resolution
    grid.info.origin.orientation.w = 1.0
    grid.data = [100 if x in (0, width - 1) or y in (0, height - 1) else 0
                 for y in range(height) for x in range(width)]
    return grid


def main():
    rospy.init_node('map_loader')
    size = rospy.get_param('~cells', 20)
    map_pub = rospy.Publisher('map', OccupancyGrid, queue_size=1, latch=True)
    map_pub.publish(room(size, size, 0.25, rospy.get_param('~frame_id', 'map')))
    rospy.spin()


if __name__ == '__main__':
    main()
