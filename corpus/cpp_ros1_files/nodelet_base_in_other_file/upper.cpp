// The nodelet: all of its ports come from its base class, defined in base.cpp.
#include <pluginlib/class_list_macros.hpp>
#include "base.h"

namespace filters
{
class Upper : public Base
{
  void process(const std_msgs::String::ConstPtr& msg) override
  {
    pub_.publish(msg);
  }
};
}  // namespace filters

PLUGINLIB_EXPORT_CLASS(filters::Upper, nodelet::Nodelet)
