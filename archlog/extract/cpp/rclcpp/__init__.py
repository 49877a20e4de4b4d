"""The rclcpp (ROS 2) readers of the C++ walker; walker.RclcppWalker is their entry."""
