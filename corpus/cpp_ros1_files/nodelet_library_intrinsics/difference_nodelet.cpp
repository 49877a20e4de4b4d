// A nodelet library of two files (depth_image_proc's): this nodelet is the one read (the fixture
// reads the first class a file of the folder exports, in name order).
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>
#include <ros/ros.h>
#include <std_msgs/Float32.h>

namespace sums
{
class DifferenceNodelet : public nodelet::Nodelet
{
  ros::Publisher pub_;

  void onInit() override
  {
    pub_ = getNodeHandle().advertise<std_msgs::Float32>("difference", 1);
  }
};
}  // namespace sums

PLUGINLIB_EXPORT_CLASS(sums::DifferenceNodelet, nodelet::Nodelet)
