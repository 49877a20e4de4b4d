"""rospy and rclpy node sources, read with Python's ast: ports (node.py), then behavior (behavior/)."""
