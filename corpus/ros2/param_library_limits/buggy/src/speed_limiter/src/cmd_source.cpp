// Sends a forward speed command at 10 Hz.
#include <chrono>
#include <memory>

#include "geometry_msgs/msg/twist.hpp"
#include "rclcpp/rclcpp.hpp"

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = rclcpp::Node::make_shared("cmd_source");
  auto pub = node->create_publisher<geometry_msgs::msg::Twist>("cmd_vel", 10);
  auto timer = node->create_wall_timer(
    std::chrono::milliseconds(100), [pub]() {
      geometry_msgs::msg::Twist cmd;
      cmd.linear.x = 1.0;
      pub->publish(cmd);
    });
  rclcpp::spin(node);
  rclcpp::shutdown();
  return 0;
}
