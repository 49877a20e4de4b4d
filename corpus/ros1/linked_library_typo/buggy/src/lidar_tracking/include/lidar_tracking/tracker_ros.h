#pragma once
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>

#include <lidar_tracking/status_reporter.h>

namespace lidar_tracking {

// Clusters scan points closer than ~max_range into tracks.
class TrackerRos {
 public:
  TrackerRos();

 private:
  void onScan(const sensor_msgs::LaserScan::ConstPtr& scan);

  ros::NodeHandle nh_;
  ros::NodeHandle pnh_;
  double max_range_;
  ros::Subscriber scan_sub_;
  ros::Publisher count_pub_;
  StatusReporter status_;
};

}  // namespace lidar_tracking
