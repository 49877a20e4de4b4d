// Rate-limits raw velocity commands before they reach the base driver.
#include <algorithm>

#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>

class VelocitySmoother {
 public:
  VelocitySmoother(ros::NodeHandle& nh, ros::NodeHandle& pnh) {
    pnh.param("max_accel", max_accel_, 1.0);
    pnh.param("rate", rate_, 20.0);
    cmd_pub_ = nh.advertise<geometry_msgs::Twist>("cmd_vel", 10);
    raw_sub_ = nh.subscribe("raw_cmd_vel", 10, &VelocitySmoother::onRawCmd, this);
    odom_sub_ = nh.subscribe("odom", 10, &VelocitySmoother::onOdom, this);
    timer_ = nh.createTimer(ros::Duration(1.0 / rate_), &VelocitySmoother::onTimer, this);
  }

 private:
  void onRawCmd(const geometry_msgs::Twist::ConstPtr& msg) { target_ = *msg; }
  void onOdom(const nav_msgs::Odometry::ConstPtr& msg) { measured_ = msg->twist.twist; }

  void onTimer(const ros::TimerEvent&) {
    const double dv = max_accel_ / rate_;
    geometry_msgs::Twist out = target_;
    out.linear.x = std::clamp(target_.linear.x, measured_.linear.x - dv, measured_.linear.x + dv);
    cmd_pub_.publish(out);
  }

  double max_accel_ = 1.0;
  double rate_ = 20.0;
  geometry_msgs::Twist target_, measured_;
  ros::Publisher cmd_pub_;
  ros::Subscriber raw_sub_, odom_sub_;
  ros::Timer timer_;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "velocity_smoother");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  VelocitySmoother smoother(nh, pnh);
  ros::spin();
  return 0;
}
