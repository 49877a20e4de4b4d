// Never reached: nothing the executable runs builds a Listener, so its subscriber is not the node's.
#include "kit.h"

namespace kit
{
Listener::Listener(ros::NodeHandle nh)
{
  sub_ = nh.subscribe("heard", 10, &Listener::heard, this);
}

void Listener::heard(const std_msgs::String::ConstPtr& msg)
{
  ROS_INFO("%s", msg->data.c_str());
}
}  // namespace kit
