"""archlog: find architecture misconfiguration bugs in ROS systems before the robot runs."""

__version__ = "0.1.0"
