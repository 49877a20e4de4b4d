#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>
#include <ros/ros.h>
#include <std_msgs/String.h>
namespace wrapped {
class C : public nodelet::Nodelet {
  void onInit() override {
    sub_ = getNodeHandle().subscribe("in_c", 1, &C::cb, this);
  }
  void cb(const std_msgs::String::ConstPtr& msg) {}
  ros::Subscriber sub_;
};
}
PLUGINLIB_EXPORT_CLASS(wrapped::C, nodelet::Nodelet)
