#pragma once
#include <ros/ros.h>

namespace lidar_tracking {

// Publishes a one-line status of the tracker.
class StatusReporter {
 public:
  StatusReporter();
  void report(int tracks);

 private:
  ros::Publisher status_pub_;
};

}  // namespace lidar_tracking
