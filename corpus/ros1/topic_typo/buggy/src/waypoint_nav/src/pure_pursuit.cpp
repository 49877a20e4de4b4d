// Pure-pursuit path tracker: follows the loaded waypoint path using odometry.
#include <cmath>

#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>

namespace {
nav_msgs::Path g_path;
ros::Publisher g_cmd_pub;
double g_lookahead = 0.8;
double g_speed = 0.5;

void pathCallback(const nav_msgs::Path::ConstPtr& msg) {
  g_path = *msg;
  ROS_INFO("received path with %zu waypoints", g_path.poses.size());
}

void odomCallback(const nav_msgs::Odometry::ConstPtr& msg) {
  geometry_msgs::Twist cmd;
  const auto& p = msg->pose.pose.position;
  const auto& q = msg->pose.pose.orientation;
  const double yaw = 2.0 * std::atan2(q.z, q.w);
  for (const auto& wp : g_path.poses) {
    const double dx = wp.pose.position.x - p.x;
    const double dy = wp.pose.position.y - p.y;
    if (std::hypot(dx, dy) < g_lookahead) continue;
    const double alpha = std::atan2(dy, dx) - yaw;
    cmd.linear.x = g_speed;
    cmd.angular.z = 2.0 * g_speed * std::sin(alpha) / g_lookahead;
    break;
  }
  g_cmd_pub.publish(cmd);
}
}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "pure_pursuit");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  pnh.param("lookahead", g_lookahead, 0.8);
  pnh.param("speed", g_speed, 0.5);
  g_cmd_pub = nh.advertise<geometry_msgs::Twist>("cmd_vel", 10);
  ros::Subscriber path_sub = nh.subscribe("base_waypoint", 1, pathCallback);
  ros::Subscriber odom_sub = nh.subscribe("odom", 10, odomCallback);
  ros::spin();
  return 0;
}
