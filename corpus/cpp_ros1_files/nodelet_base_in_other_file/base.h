// The base class of a library's filter nodelets (pcl_ros's Feature): it sets up the ports.
#pragma once
#include <nodelet/nodelet.h>
#include <ros/ros.h>
#include <std_msgs/String.h>

namespace filters
{
class Base : public nodelet::Nodelet
{
protected:
  ros::Publisher pub_;
  ros::Subscriber sub_;
  void onInit() override;
  virtual void process(const std_msgs::String::ConstPtr& msg) = 0;
  virtual void childInit(ros::NodeHandle& nh) = 0;  // each filter's own ports
};
}  // namespace filters
