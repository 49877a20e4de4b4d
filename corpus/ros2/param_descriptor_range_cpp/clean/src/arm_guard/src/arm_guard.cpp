// Publishes a stop flag when the measured effort passes max_effort; the ranges of its parameters
// are declared with ParameterDescriptor, so rclcpp rejects a value outside them at start-up.
#include <memory>

#include "rcl_interfaces/msg/parameter_descriptor.hpp"
#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/bool.hpp"
#include "std_msgs/msg/float64.hpp"

class ArmGuard : public rclcpp::Node
{
public:
  ArmGuard()
  : Node("arm_guard")
  {
    rcl_interfaces::msg::ParameterDescriptor effort;
    effort.description = "Effort above which the arm is stopped (N m).";
    rcl_interfaces::msg::FloatingPointRange effort_range;
    effort_range.set__from_value(0.0).set__to_value(40.0);
    effort.floating_point_range.push_back(effort_range);
    max_effort_ = declare_parameter("max_effort", 20.0, effort);

    rcl_interfaces::msg::ParameterDescriptor joints;
    joints.read_only = true;
    rcl_interfaces::msg::IntegerRange joint_range;
    joint_range.from_value = 1;
    joint_range.to_value = 7;
    joints.integer_range = {joint_range};
    joint_count_ = declare_parameter("joint_count", 6, joints);

    stop_ = create_publisher<std_msgs::msg::Bool>("arm_stop", 10);
    effort_sub_ = create_subscription<std_msgs::msg::Float64>(
      "arm_effort", 10, [this](std_msgs::msg::Float64::SharedPtr msg) {
        std_msgs::msg::Bool stop;
        stop.data = msg->data > max_effort_;
        stop_->publish(stop);
      });
  }

private:
  double max_effort_;
  int64_t joint_count_;
  rclcpp::Publisher<std_msgs::msg::Bool>::SharedPtr stop_;
  rclcpp::Subscription<std_msgs::msg::Float64>::SharedPtr effort_sub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<ArmGuard>());
  rclcpp::shutdown();
  return 0;
}
