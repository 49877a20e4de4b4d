// The tracker node: every port lives in the lidar_tracking_ros library it links.
#include <lidar_tracking/tracker_ros.h>

int main(int argc, char** argv) {
  ros::init(argc, argv, "tracker");
  lidar_tracking::TrackerRos tracker;
  ros::spin();
  return 0;
}
