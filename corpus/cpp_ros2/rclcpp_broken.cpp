// A node that does not compile: a type that does not exist, and a statement cut short. The calls
// the parser loses are read from the tokens; the node is marked incomplete.
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"

class Relay : public rclcpp::Node
{
public:
  Relay()
  : Node("relay")
  {
    UnknownConfig config(this);
    out_pub_ = create_publisher<std_msgs::msg::String>("relay/out", rclcpp::QoS(5).best_effort());
    in_sub_ = this->create_subscription<std_msgs::msg::String>(
      config.input_topic(), rclcpp::SensorDataQoS(), [this](std_msgs::msg::String::SharedPtr msg) {
        out_pub_->publish(*msg)
      });
    echo_sub_ = create_subscription<std_msgs::msg::String>("relay/echo", 1,
      [](std_msgs::msg::String::SharedPtr) {});
  }

private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr out_pub_;
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr in_sub_;
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr echo_sub_;
};
