"""Launch files: ROS 1 XML and ROS 2 XML, YAML and Python, read into one LaunchConfig."""
