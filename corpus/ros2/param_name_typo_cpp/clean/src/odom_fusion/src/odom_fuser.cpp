// Smooths the odometry of the topic its parameter names and republishes it.
#include <functional>
#include <memory>
#include <string>

#include "nav_msgs/msg/odometry.hpp"
#include "rclcpp/rclcpp.hpp"

class OdomFuser : public rclcpp::Node
{
public:
  OdomFuser()
  : Node("odom_fuser")
  {
    const auto input = this->declare_parameter<std::string>("input_topic", "odom");
    smoothing_ = this->declare_parameter<double>("smoothing", 0.2);
    pub_ = this->create_publisher<nav_msgs::msg::Odometry>("odom/smoothed", 10);
    sub_ = this->create_subscription<nav_msgs::msg::Odometry>(
      input, 10, std::bind(&OdomFuser::on_odom, this, std::placeholders::_1));
  }

private:
  void on_odom(const nav_msgs::msg::Odometry & odom)
  {
    nav_msgs::msg::Odometry out = odom;
    out.twist.twist.linear.x = smoothing_ * odom.twist.twist.linear.x;
    pub_->publish(out);
  }

  double smoothing_{0.2};
  rclcpp::Publisher<nav_msgs::msg::Odometry>::SharedPtr pub_;
  rclcpp::Subscription<nav_msgs::msg::Odometry>::SharedPtr sub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<OdomFuser>());
  rclcpp::shutdown();
  return 0;
}
