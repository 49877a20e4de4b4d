// Reporter::start is reached through a virtual call on a Stage pointer (every override of a called
// virtual method counts, Auditor's too: which object the pointer holds is not followed).
#include "kit.h"

namespace kit
{
void Reporter::start(ros::NodeHandle& nh)
{
  pub_ = nh.advertise<std_msgs::String>("report", 1);
}

void Auditor::start(ros::NodeHandle& nh)
{
  pub_ = nh.advertise<std_msgs::String>("audit", 1);
}

Listener* make_listener()
{
  return new Listener;  // a factory nobody calls: no Listener either
}
}  // namespace kit
