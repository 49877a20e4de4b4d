// The smoother's header includes its generated dynamic_reconfigure Config, absent from a source
// checkout: clang stops at it, so the Smoother class is not known to the nodelet's file.
#pragma once
#include <dynamic_reconfigure/server.h>
#include <geometry_msgs/Twist.h>
#include <ros/ros.h>
#include "smoother/paramsConfig.h"

namespace smoother {
class Smoother {
 public:
  bool init(ros::NodeHandle& nh);

 private:
  void velocityCB(const geometry_msgs::Twist::ConstPtr& msg);
  dynamic_reconfigure::Server<smoother::paramsConfig>* server_;
  ros::Subscriber raw_sub_;
  ros::Publisher smooth_pub_;
};
}  // namespace smoother
