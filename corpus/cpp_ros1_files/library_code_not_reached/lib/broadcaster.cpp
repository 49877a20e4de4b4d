// Reached: main's Sender has a Broadcaster member, built by Sender's constructor.
#include "kit.h"

namespace kit
{
Broadcaster::Broadcaster()
{
  pub_ = nh_.advertise<std_msgs::String>("chatter", 10);
}

void Broadcaster::send(const std::string& text)
{
  std_msgs::String msg;
  msg.data = text;
  pub_.publish(msg);
}
}  // namespace kit
