// Follows the odometry towards a fixed point with a proportional controller.
#include <memory>

#include "geometry_msgs/msg/twist_stamped.hpp"
#include "nav_msgs/msg/odometry.hpp"
#include "rclcpp/rclcpp.hpp"

class PathFollower : public rclcpp::Node
{
public:
  PathFollower()
  : Node("path_follower")
  {
    gain_ = declare_parameter("gain", 0.8);
    cmd_pub_ = create_publisher<geometry_msgs::msg::TwistStamped>("cmd_vel", 10);
    odom_sub_ = create_subscription<nav_msgs::msg::Odometry>(
      "odom", 10, [this](nav_msgs::msg::Odometry::ConstSharedPtr odom) {follow(*odom);});
  }

private:
  void follow(const nav_msgs::msg::Odometry & odom)
  {
    geometry_msgs::msg::TwistStamped command;
    command.header = odom.header;
    command.twist.linear.x = gain_ * (1.0 - odom.pose.pose.position.x);
    cmd_pub_->publish(command);
  }

  double gain_;
  rclcpp::Publisher<geometry_msgs::msg::TwistStamped>::SharedPtr cmd_pub_;
  rclcpp::Subscription<nav_msgs::msg::Odometry>::SharedPtr odom_sub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<PathFollower>());
  rclcpp::shutdown();
  return 0;
}
