// A ROS 1 node that loads a planner as a pluginlib class named by a parameter: the planner's
// ports are not in this file (the load is a hole of the node).
#include <string>

#include <boost/shared_ptr.hpp>
#include <geometry_msgs/PoseStamped.h>
#include <pluginlib/class_loader.h>
#include <ros/ros.h>

namespace fleet
{
class Planner
{
public:
  virtual ~Planner() {}
  virtual void initialize(const std::string & name) = 0;
};
}  // namespace fleet

int main(int argc, char ** argv)
{
  ros::init(argc, argv, "planner_host");
  ros::NodeHandle nh("~");
  ros::Publisher goal_pub = nh.advertise<geometry_msgs::PoseStamped>("goal", 1);
  std::string type;
  nh.param<std::string>("planner", type, "fleet/StraightLine");
  pluginlib::ClassLoader<fleet::Planner> loader("fleet", "fleet::Planner");
  boost::shared_ptr<fleet::Planner> planner = loader.createInstance(type);
  planner->initialize("planner");
  ros::spin();
}
