// NodeHandle::getNamespace() is the handle's namespace, resolved and remapped ("/" at the root,
// "/robot1" in a group; a private handle's is the node's name), and ros::this_node::getNamespace()
// the node's. A name built from it is global; the usual edit that makes it relative (erase the
// leading slash) gives "robot1/odom", which roscpp resolves again in the handle's namespace.
#include <ros/ros.h>
#include <nav_msgs/Odometry.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/String.h>

void on_command(const std_msgs::String::ConstPtr& msg) {}

class Relay {
 public:
  explicit Relay(ros::NodeHandle& nh) {
    topic_ = "relay";  // an assignment to a member: no variable on its left
    std::string ns = nh.getNamespace();
    ns.erase(0, 1);
    pub_ = nh.advertise<std_msgs::String>(ns + "/" + topic_, 1);
  }

 private:
  std::string topic_;
  ros::Publisher pub_;
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "odometer");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  ros::NodeHandle arm("arm");
  std::string ns = nh.getNamespace();
  if (!ns.empty() && ns[0] == '/')
    ns.erase(0, 1);
  ros::Publisher odom = nh.advertise<nav_msgs::Odometry>(ns + "/odom", 1);
  ros::Publisher status = nh.advertise<std_msgs::String>(nh.getNamespace() + "/status", 1);
  std::string private_ns = pnh.getNamespace().substr(1);
  ros::Publisher scan = nh.advertise<sensor_msgs::LaserScan>(private_ns + "/scan", 1);
  std::string node_ns = ros::this_node::getNamespace();
  ros::Publisher heartbeat = nh.advertise<std_msgs::String>(node_ns + "/heartbeat", 1);
  std::string arm_ns = arm.getNamespace();
  arm_ns = arm_ns.substr(1);
  ros::Subscriber command = nh.subscribe(arm_ns + "/command", 1, on_command);
  std::string chosen = nh.getNamespace();
  if (argc > 2)
    chosen.erase(0, 1);
  ros::Publisher debug = nh.advertise<std_msgs::String>(chosen + "/debug", 1);
  Relay relay(nh);
  ros::NodeHandle plugin(pnh, argv[1]);  // a namespace known only at run time, under the private one
  ros::Publisher state = plugin.advertise<std_msgs::String>("state", 1);
  ros::spin();
  return 0;
}
