"""Driver of the spinning 3D lidar: an empty cloud every 0.1 s (simulated)."""

import rclpy
from sensor_msgs.msg import PointCloud2


def main():
    rclpy.init()
    node = rclpy.create_node("points_driver")
    publisher = node.create_publisher(PointCloud2, "points", 5)

    def publish():
        cloud = PointCloud2()
        cloud.header.frame_id = "spinning_lidar"
        publisher.publish(cloud)

    node.create_timer(0.1, publish)
    rclpy.spin(node)
    rclpy.shutdown()
