// ros::this_node::getName() is the node's full name (/ns/name), not a ~name: a NodeHandle method
// given it, or a name built from it, is fine (nodelet.cpp reads its parameters so). Only the
// written ~name (/wrong) makes roscpp throw.
#include <ros/ros.h>
#include <std_msgs/String.h>

// nodelet.cpp's Loader: the name reaches the NodeHandle through a parameter
void load(ros::NodeHandle& n, const std::string& name)
{
  XmlRpc::XmlRpcValue param;
  n.setParam(name, param);
}

int main(int argc, char** argv)
{
  ros::init(argc, argv, "namer");
  ros::NodeHandle n;
  std::string params;
  n.getParam(ros::this_node::getName(), params);
  double rate = 1.0;
  n.param(ros::this_node::getName() + "/rate", rate, 2.0);
  const std::string self = ros::this_node::getName();
  ros::Publisher status = n.advertise<std_msgs::String>(self + "/status", 1);
  XmlRpc::XmlRpcValue param;
  std::string node_name = ros::this_node::getName ();
  n.getParam (node_name, param);
  load(n, ros::this_node::getName());
  ros::Publisher wrong = n.advertise<std_msgs::String>("~wrong", 1);
  ros::spin();
  return 0;
}
