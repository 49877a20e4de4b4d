// The handle, the topic and the flag come from main.cpp (tf2_ros's BufferServer, pcl_ros's
// childInit): no call in this file gives them, the calls in the executable's other files do.
#include "relay.h"

Relay::Relay(ros::NodeHandle& nh, const std::string& topic, bool verbose)
{
  sub_ = nh.subscribe(topic, 1, &Relay::forward, this);
  pub_ = nh.advertise<std_msgs::String>(topic + "_relayed", 1);
  if (verbose && nh.ok())
  {
    debug_ = nh.advertise<std_msgs::String>("debug", 1);
  }
}

void Relay::forward(const std_msgs::String::ConstPtr& msg)
{
  pub_.publish(msg);
}

void Counter::setup(ros::NodeHandle& nh)
{
  pub_ = nh.advertise<std_msgs::String>("count", 1);
}
