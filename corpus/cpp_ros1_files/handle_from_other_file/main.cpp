// Hands a private handle, a topic and a parameter's value to Relay's constructor, and a handle to
// a virtual method that Counter (in relay.cpp) overrides.
#include <memory>
#include "relay.h"

int main(int argc, char** argv)
{
  ros::init(argc, argv, "relay");
  ros::NodeHandle pnh("~");
  bool verbose;
  pnh.param("verbose", verbose, false);
  Relay relay(pnh, "cmd", verbose);
  std::unique_ptr<Stage> stage(new Counter);
  ros::NodeHandle stats("stats");
  stage->setup(stats);
  ros::spin();
}
