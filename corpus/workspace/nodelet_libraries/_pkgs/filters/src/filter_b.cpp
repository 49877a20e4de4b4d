#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>
#include <ros/ros.h>
#include <std_msgs/String.h>
namespace filters {
class FilterB : public nodelet::Nodelet {
  void onInit() override {
    pub_ = getPrivateNodeHandle().advertise<std_msgs::String>("out_b", 1);
  }
  ros::Publisher pub_;
};
}
PLUGINLIB_EXPORT_CLASS(filters::FilterB, nodelet::Nodelet)
