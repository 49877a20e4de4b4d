// A node publishing and subscribing a custom C++ type that a TypeAdapter maps onto a ROS message:
// on the wire (and in the graph) the ports carry the message.
#include <memory>
#include <string>

#include "rclcpp/rclcpp.hpp"
#include "rclcpp/type_adapter.hpp"
#include "std_msgs/msg/string.hpp"

namespace lab
{
struct Label
{
  std::string text;
};
}  // namespace lab

template<>
struct rclcpp::TypeAdapter<lab::Label, std_msgs::msg::String>
{
  using is_specialized = std::true_type;
  using custom_type = lab::Label;
  using ros_message_type = std_msgs::msg::String;
};

RCLCPP_USING_CUSTOM_TYPE_AS_ROS_MESSAGE_TYPE(lab::Label, std_msgs::msg::String);

class Labeller : public rclcpp::Node
{
public:
  Labeller()
  : Node("labeller")
  {
    pub_ = create_publisher<lab::Label>("labels", 10);
    sub_ = create_subscription<lab::Label>(
      "raw_labels", 10, [this](const lab::Label & label) {pub_->publish(label);});
  }

private:
  rclcpp::Publisher<lab::Label>::SharedPtr pub_;
  rclcpp::Subscription<lab::Label>::SharedPtr sub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Labeller>());
  rclcpp::shutdown();
}
