// Differential-drive base driver: consumes velocity commands, reports wheel odometry.
#include <cmath>

#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>

namespace {
double g_v = 0.0, g_w = 0.0;
double g_x = 0.0, g_y = 0.0, g_yaw = 0.0;

void cmdVelCallback(const geometry_msgs::Twist::ConstPtr& msg) {
  g_v = msg->linear.x;
  g_w = msg->angular.z;
}
}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "diff_drive_base");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  std::string frame_id = pnh.param<std::string>("odom_frame", "odom");
  ros::Publisher odom_pub = nh.advertise<nav_msgs::Odometry>("odom", 20);
  ros::Subscriber cmd_sub = nh.subscribe("cmd_vel", 10, cmdVelCallback);

  ros::Rate rate(pnh.param("rate", 50.0));
  ros::Time last = ros::Time::now();
  while (ros::ok()) {
    ros::spinOnce();
    const ros::Time now = ros::Time::now();
    const double dt = (now - last).toSec();
    last = now;
    g_yaw += g_w * dt;
    g_x += g_v * std::cos(g_yaw) * dt;
    g_y += g_v * std::sin(g_yaw) * dt;
    nav_msgs::Odometry odom;
    odom.header.stamp = now;
    odom.header.frame_id = frame_id;
    odom.pose.pose.position.x = g_x;
    odom.pose.pose.position.y = g_y;
    odom.pose.pose.orientation.z = std::sin(g_yaw / 2.0);
    odom.pose.pose.orientation.w = std::cos(g_yaw / 2.0);
    odom.twist.twist.linear.x = g_v;
    odom.twist.twist.angular.z = g_w;
    odom_pub.publish(odom);
    rate.sleep();
  }
  return 0;
}
