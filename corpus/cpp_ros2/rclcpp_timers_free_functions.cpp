// A heartbeat node made with std::make_shared<rclcpp::Node>: timers from chrono literals, chrono
// durations, rclcpp::Duration and a loop rate; entities made with rclcpp's free functions; a
// generic publisher whose type is a string.
#include <chrono>
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/empty.hpp"
#include "std_msgs/msg/u_int32.hpp"

using namespace std::chrono_literals;

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("heartbeat");
  auto beat_pub = rclcpp::create_publisher<std_msgs::msg::UInt32>(node, "beat", 5);
  auto reset_sub = rclcpp::create_subscription<std_msgs::msg::Empty>(
    node, "reset", rclcpp::QoS(1), [](std_msgs::msg::Empty::ConstSharedPtr) {});
  auto raw_pub = node->create_generic_publisher("raw_beat", "std_msgs/msg/UInt32", rclcpp::QoS(1));
  uint32_t count = 0;
  auto fast = node->create_wall_timer(
    1500us, [&count]() {++count;});
  auto slow = node->create_wall_timer(std::chrono::minutes(1), [&count]() {count = 0;});
  auto ros_timer = rclcpp::create_timer(
    node, node->get_clock(), rclcpp::Duration::from_seconds(0.25), [&]() {
      std_msgs::msg::UInt32 msg;
      msg.data = count;
      beat_pub->publish(msg);
    });
  auto periodic = rclcpp::create_timer(node, node->get_clock(), rclcpp::Duration(2, 500000000), []() {});
  rclcpp::WallRate rate(20.0);
  while (rclcpp::ok()) {
    rclcpp::spin_some(node);
    rate.sleep();
  }
  rclcpp::shutdown();
  return 0;
}
