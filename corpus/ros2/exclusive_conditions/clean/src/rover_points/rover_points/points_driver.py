"""Driver of the rover's 3D lidar (either model; `frame` names it): an empty cloud every 0.1 s (simulated)."""

import rclpy
from sensor_msgs.msg import PointCloud2


def main():
    rclpy.init()
    node = rclpy.create_node("points_driver")
    frame = node.declare_parameter("frame", "lidar").value
    publisher = node.create_publisher(PointCloud2, "points", 5)

    def publish():
        cloud = PointCloud2()
        cloud.header.frame_id = frame
        publisher.publish(cloud)

    node.create_timer(0.1, publish)
    rclpy.spin(node)
    rclpy.shutdown()
