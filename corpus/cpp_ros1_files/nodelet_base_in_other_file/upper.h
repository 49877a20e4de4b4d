// The nodelet's class, with the override its base calls (from base.cpp) defined in the header
// (pcl_ros's NormalEstimation::childInit): its port is on the handle the base passes.
#pragma once
#include "base.h"

namespace filters
{
class Upper : public Base
{
  ros::Publisher count_;

  void process(const std_msgs::String::ConstPtr& msg) override;

  void childInit(ros::NodeHandle& nh) override
  {
    count_ = nh.advertise<std_msgs::String>("count", 1);
  }
};
}  // namespace filters
