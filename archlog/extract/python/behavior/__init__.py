"""Behavior of rospy and rclpy nodes: the triggers, guards and state writes of publish calls (triggers.py)."""
