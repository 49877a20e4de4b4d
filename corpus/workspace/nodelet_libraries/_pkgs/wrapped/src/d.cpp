#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>
#include <ros/ros.h>
#include <std_msgs/String.h>
namespace wrapped {
class D : public nodelet::Nodelet {
  void onInit() override {
    sub_ = getNodeHandle().subscribe("in_d", 1, &D::cb, this);
  }
  void cb(const std_msgs::String::ConstPtr& msg) {}
  ros::Subscriber sub_;
};
}
PLUGINLIB_EXPORT_CLASS(wrapped::D, nodelet::Nodelet)
