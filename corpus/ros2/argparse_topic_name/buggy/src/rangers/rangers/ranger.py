"""A range sensor driver: which sensor it reads is given on its command line."""

import argparse

import rclpy
from sensor_msgs.msg import Range


def main():
    parser = argparse.ArgumentParser(description="Publish one range sensor's readings.")
    parser.add_argument("sensor", nargs="?", default="front", help="the sensor's name")
    parser.add_argument("--rate", type=float, default=10.0, help="readings per second")
    parser.add_argument("--filtered", action="store_true", help="publish the median-filtered readings")
    args, _ros_arguments = parser.parse_known_args()

    rclpy.init()
    node = rclpy.create_node(f"{args.sensor}_ranger")
    topic = args.sensor + ("/range_filtered" if args.filtered else "/range")
    publisher = node.create_publisher(Range, topic, 10)

    def publish():
        reading = Range()
        reading.header.frame_id = args.sensor
        reading.max_range = 4.0
        reading.range = 1.0
        publisher.publish(reading)

    node.create_timer(1.0 / args.rate, publish)
    rclpy.spin(node)
    rclpy.shutdown()
