// A trajectory generator in the style of a global-variable ROS 1 node: it waits for a first odometry
// pose, then publishes a trajectory in its main loop (rate from a parameter with a default); its
// status is published on every cycle, and once at start-up.
#include <geometry_msgs/PoseStamped.h>
#include <nav_msgs/Odometry.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <std_msgs/String.h>

static geometry_msgs::PoseStamped g_pose;
static bool g_pose_received = false;
static int g_cycles;

void odomCallback(const nav_msgs::Odometry::ConstPtr& msg)
{
  g_pose.header = msg->header;
  g_pose.pose = msg->pose.pose;
  g_pose_received = true;
}

int main(int argc, char** argv)
{
  ros::init(argc, argv, "trajectory_gen");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  double rate_hz;
  pnh.param("rate", rate_hz, 10.0);
  ros::Publisher traj_pub = nh.advertise<nav_msgs::Path>("trajectory", 1);
  ros::Publisher status_pub = pnh.advertise<std_msgs::String>("status", 1, true);
  ros::Subscriber odom_sub = nh.subscribe("odom_pose", 1, odomCallback);

  std_msgs::String status;
  status.data = "starting";
  status_pub.publish(status);

  ros::Rate loop_rate(rate_hz);
  while (ros::ok()) {
    ros::spinOnce();
    ++g_cycles;
    status.data = g_pose_received ? "tracking" : "waiting for odom_pose";
    status_pub.publish(status);
    if (!g_pose_received) {
      loop_rate.sleep();
      continue;
    }
    nav_msgs::Path path;
    path.header = g_pose.header;
    path.poses.push_back(g_pose);
    traj_pub.publish(path);
    loop_rate.sleep();
  }
  return 0;
}
