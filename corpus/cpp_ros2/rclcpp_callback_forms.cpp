// A battery monitor subscribing with every callback form rclcpp accepts, built in main() with
// rclcpp::Node::make_shared and used through node-> calls; one private (~/) topic.
#include <functional>
#include <memory>
#include <string>

#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/battery_state.hpp"
#include "std_msgs/msg/bool.hpp"
#include "std_msgs/msg/string.hpp"

using std::placeholders::_1;
using std::placeholders::_2;

static bool g_low = false;

void on_dock_state(const std_msgs::msg::Bool::SharedPtr msg)
{
  g_low = g_low && !msg->data;
}

class Monitor
{
public:
  explicit Monitor(rclcpp::Node::SharedPtr node)
  : node_(node)
  {
    battery_sub_ = node_->create_subscription<sensor_msgs::msg::BatteryState>(
      "battery", 10, std::bind(&Monitor::on_battery, this, _1));
    info_sub_ = node_->create_subscription<sensor_msgs::msg::BatteryState>(
      "battery", 10, std::bind(&Monitor::on_battery_with_info, this, _1, _2));
  }

  void on_battery(const sensor_msgs::msg::BatteryState::ConstSharedPtr msg)
  {
    g_low = msg->percentage < 0.15f;
  }

  void on_battery_with_info(const sensor_msgs::msg::BatteryState::ConstSharedPtr msg, const rclcpp::MessageInfo &)
  {
    g_low = g_low || msg->voltage < 10.5f;
  }

private:
  rclcpp::Node::SharedPtr node_;
  rclcpp::Subscription<sensor_msgs::msg::BatteryState>::SharedPtr battery_sub_;
  rclcpp::Subscription<sensor_msgs::msg::BatteryState>::SharedPtr info_sub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = rclcpp::Node::make_shared("battery_monitor", "power");
  Monitor monitor(node);
  auto warn_pub = node->create_publisher<std_msgs::msg::String>("~/warnings", 5);
  auto dock_sub = node->create_subscription<std_msgs::msg::Bool>("dock/state", 1, on_dock_state);
  std::function<void(std_msgs::msg::String::UniquePtr)> relay =
    [warn_pub](std_msgs::msg::String::UniquePtr msg) {warn_pub->publish(std::move(msg));};
  auto relay_sub = node->create_subscription<std_msgs::msg::String>("operator/notes", 5, relay);
  auto lambda_sub = node->create_subscription<std_msgs::msg::Bool>(
    "estop", rclcpp::QoS(1),
    [warn_pub](const std_msgs::msg::Bool & msg) {
      if (msg.data) {
        std_msgs::msg::String text;
        text.data = "emergency stop";
        warn_pub->publish(text);
      }
    });
  rclcpp::spin(node);
  rclcpp::shutdown();
  return 0;
}
