// The limiter: its parameters are declared by the ParamListener that generate_parameter_library
// builds from speed_limiter_parameters.yaml (the generated header is not in the source tree).
#include <algorithm>
#include <memory>

#include "geometry_msgs/msg/twist.hpp"
#include "rclcpp/rclcpp.hpp"
#include "speed_limiter/speed_limiter_parameters.hpp"

class SpeedLimiter : public rclcpp::Node
{
public:
  SpeedLimiter()
  : Node("speed_limiter")
  {
    listener_ = std::make_shared<speed_limiter::ParamListener>(get_node_parameters_interface());
    params_ = listener_->get_params();
    pub_ = create_publisher<geometry_msgs::msg::Twist>("cmd_vel_limited", 10);
    sub_ = create_subscription<geometry_msgs::msg::Twist>(
      "cmd_vel", 10, [this](geometry_msgs::msg::Twist::SharedPtr msg) {
        msg->linear.x = std::min(msg->linear.x, params_.max_linear_speed);
        pub_->publish(*msg);
      });
  }

private:
  std::shared_ptr<speed_limiter::ParamListener> listener_;
  speed_limiter::Params params_;
  rclcpp::Publisher<geometry_msgs::msg::Twist>::SharedPtr pub_;
  rclcpp::Subscription<geometry_msgs::msg::Twist>::SharedPtr sub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<SpeedLimiter>());
  rclcpp::shutdown();
  return 0;
}
