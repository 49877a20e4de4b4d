"""C++ extraction (roscpp and rclcpp) with libclang: plumbing, walkers, behavior, stand-in headers."""
