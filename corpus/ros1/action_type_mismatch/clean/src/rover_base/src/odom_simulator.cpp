// Kinematic unicycle: integrates the last velocity command and publishes odometry at a fixed rate.
#include <cmath>
#include <string>

#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>

class OdomSimulator {
 public:
  OdomSimulator(ros::NodeHandle& nh, ros::NodeHandle& pnh) {
    pnh.param<std::string>("odom_frame", odom_frame_, "odom");
    pnh.param<std::string>("base_frame", base_frame_, "base_link");
    cmd_sub_ = nh.subscribe("cmd_vel", 10, &OdomSimulator::onCmd, this);
    odom_pub_ = nh.advertise<nav_msgs::Odometry>("odom", 10);
  }

  void step(double dt) {
    yaw_ += cmd_.angular.z * dt;
    x_ += cmd_.linear.x * std::cos(yaw_) * dt;
    y_ += cmd_.linear.x * std::sin(yaw_) * dt;
    nav_msgs::Odometry odom;
    odom.header.stamp = ros::Time::now();
    odom.header.frame_id = odom_frame_;
    odom.child_frame_id = base_frame_;
    odom.pose.pose.position.x = x_;
    odom.pose.pose.position.y = y_;
    odom.pose.pose.orientation.z = std::sin(yaw_ / 2.0);
    odom.pose.pose.orientation.w = std::cos(yaw_ / 2.0);
    odom.twist.twist = cmd_;
    odom_pub_.publish(odom);
  }

 private:
  void onCmd(const geometry_msgs::Twist::ConstPtr& cmd) { cmd_ = *cmd; }

  ros::Subscriber cmd_sub_;
  ros::Publisher odom_pub_;
  geometry_msgs::Twist cmd_;
  std::string odom_frame_, base_frame_;
  double x_ = 0.0, y_ = 0.0, yaw_ = 0.0;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "odom_simulator");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  double rate;
  pnh.param("rate", rate, 30.0);
  OdomSimulator sim(nh, pnh);
  ros::Rate loop(rate);
  while (ros::ok()) {
    ros::spinOnce();
    sim.step(1.0 / rate);
    loop.sleep();
  }
  return 0;
}
