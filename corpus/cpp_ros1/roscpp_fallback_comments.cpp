// A node whose planner header is missing here, so libclang's AST is incomplete and its calls are
// read from the text: a subscription left in a comment (line or block) is not a port, while a call
// after a string holding "//" is kept.
#include <ros/ros.h>
#include <std_msgs/String.h>

#include "route_planner/planner_core.h"

void onRoute(const std_msgs::String::ConstPtr& msg) { route_planner::accept(msg->data); }

int main(int argc, char** argv) {
  ros::init(argc, argv, "route_follower");
  ros::NodeHandle nh;
  route_planner::Core core(nh);
  // ros::Subscriber ctrl_sub = nh.subscribe("/ctrl_cmd", 1, &onRoute);
  /* ros::Publisher old_pub = nh.advertise<std_msgs::String>("legacy_route", 1);
     kept for the old planner */
  ros::Subscriber route_sub = nh.subscribe("route", 1, &onRoute);
  ROS_INFO("docs: http://example.com/route"); ros::Publisher echo_pub = nh.advertise<std_msgs::String>("route_echo", 1);
  ros::spin();
  return 0;
}
