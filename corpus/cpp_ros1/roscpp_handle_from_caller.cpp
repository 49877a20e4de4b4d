// A function of a node's library whose NodeHandle comes from a caller in another source file of
// the executable: the port's name is unknown, and the unknown says where the handle comes from.
#include <ros/ros.h>
#include <std_msgs/Bool.h>

namespace estop {

ros::Publisher advertise_stop(ros::NodeHandle& nh) {
  return nh.advertise<std_msgs::Bool>("stop", 1, true);
}

}  // namespace estop
