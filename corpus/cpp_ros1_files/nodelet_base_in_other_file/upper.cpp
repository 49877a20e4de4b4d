// The nodelet: its ports come from its base class (base.cpp) and the override in upper.h.
#include <pluginlib/class_list_macros.hpp>
#include "upper.h"

namespace filters
{
void Upper::process(const std_msgs::String::ConstPtr& msg)
{
  pub_.publish(msg);
}
}  // namespace filters

PLUGINLIB_EXPORT_CLASS(filters::Upper, nodelet::Nodelet)
