// Publishes wheel odometry at 50 Hz.
#include <chrono>
#include <memory>

#include "nav_msgs/msg/odometry.hpp"
#include "rclcpp/rclcpp.hpp"

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = rclcpp::Node::make_shared("wheel_odometry");
  auto pub = node->create_publisher<nav_msgs::msg::Odometry>("wheel/odom", 10);
  auto timer = node->create_wall_timer(
    std::chrono::milliseconds(20), [node, pub]() {
      nav_msgs::msg::Odometry odom;
      odom.header.stamp = node->now();
      pub->publish(odom);
    });
  rclcpp::spin(node);
  rclcpp::shutdown();
  return 0;
}
