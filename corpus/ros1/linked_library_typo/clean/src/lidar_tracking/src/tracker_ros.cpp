#include <lidar_tracking/tracker_ros.h>

#include <std_msgs/Int32.h>

namespace lidar_tracking {

TrackerRos::TrackerRos() : pnh_("~") {
  pnh_.param("max_range", max_range_, 5.0);
  count_pub_ = nh_.advertise<std_msgs::Int32>("track_count", 5);
  scan_sub_ = nh_.subscribe("scan_filtered", 5, &TrackerRos::onScan, this);
}

void TrackerRos::onScan(const sensor_msgs::LaserScan::ConstPtr& scan) {
  int tracks = 0;
  bool inside = false;
  for (float range : scan->ranges) {
    const bool near = range < max_range_;
    tracks += near && !inside;
    inside = near;
  }
  std_msgs::Int32 count;
  count.data = tracks;
  count_pub_.publish(count);
  status_.report(tracks);
}

}  // namespace lidar_tracking
