#include <lidar_tracking/status_reporter.h>

#include <std_msgs/String.h>

namespace lidar_tracking {

StatusReporter::StatusReporter() {
  ros::NodeHandle nh;
  status_pub_ = nh.advertise<std_msgs::String>("tracker_status", 1, true);
}

void StatusReporter::report(int tracks) {
  std_msgs::String msg;
  msg.data = std::to_string(tracks) + " tracks";
  status_pub_.publish(msg);
}

}  // namespace lidar_tracking
