// The base's methods, in their own file, which mentions Upper (a class it does not see) in this
// comment: the file is read first, before the nodelet's file tells which bases Upper has, and is
// read again once they are known.
#include "base.h"

namespace filters
{
void Base::onInit()
{
  ros::NodeHandle& pnh = getPrivateNodeHandle();
  pub_ = pnh.advertise<std_msgs::String>("output", 1);
  sub_ = pnh.subscribe("input", 1, &Base::process, this);
  childInit(pnh);
}
}  // namespace filters
