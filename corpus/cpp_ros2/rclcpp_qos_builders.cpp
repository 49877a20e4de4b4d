// A teleoperation multiplexer: QoS from rclcpp::QoS constructors and builder chains, QoS objects
// held in variables and members and changed statement by statement (one change under a
// condition: that policy is unknown), a helper returning a QoS, a QoS passed as a parameter.
#include <chrono>
#include <memory>

#include "geometry_msgs/msg/twist.hpp"
#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/bool.hpp"
#include "std_msgs/msg/string.hpp"

using namespace std::chrono_literals;

namespace
{
rclcpp::QoS command_qos()
{
  return rclcpp::QoS(rclcpp::KeepLast(1)).best_effort().deadline(100ms);
}
}  // namespace

class TeleopMux : public rclcpp::Node
{
public:
  TeleopMux()
  : Node("teleop_mux"),
    lock_qos_(rclcpp::QoS(1).transient_local())
  {
    joy_sub_ = create_subscription<geometry_msgs::msg::Twist>(
      "joy_vel", command_qos(), [this](geometry_msgs::msg::Twist::SharedPtr msg) {forward(*msg);});
    nav_sub_ = create_subscription<geometry_msgs::msg::Twist>(
      "nav_vel", rclcpp::QoS(rclcpp::KeepAll()).reliable().durability_volatile().keep_last(5),
      [this](geometry_msgs::msg::Twist::SharedPtr msg) {forward(*msg);});
    lock_sub_ = create_subscription<std_msgs::msg::Bool>(
      "lock", lock_qos_, [this](std_msgs::msg::Bool::SharedPtr msg) {locked_ = msg->data;});

    rclcpp::QoS out_qos(10);
    out_qos.keep_last(2);
    out_qos.deadline(rclcpp::Duration(0, 50000000)).lifespan(std::chrono::milliseconds(200));
    out_qos.liveliness(rclcpp::LivelinessPolicy::ManualByTopic).liveliness_lease_duration(1s);
    cmd_pub_ = create_publisher<geometry_msgs::msg::Twist>("cmd_vel", out_qos);

    auto status_qos = rclcpp::QoS(rclcpp::KeepLast(3));
    if (declare_parameter("latched_status", true)) {
      status_qos.durability(rclcpp::DurabilityPolicy::TransientLocal);
    }
    status_qos.reliability(rclcpp::ReliabilityPolicy::Reliable);
    status_pub_ = create_publisher<std_msgs::msg::String>("status", status_qos);

    history_pub_ = make_log_publisher("history", rclcpp::QoS(rclcpp::KeepAll()).history(rclcpp::HistoryPolicy::KeepAll));
  }

private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr make_log_publisher(
    const std::string & topic, const rclcpp::QoS & qos)
  {
    return create_publisher<std_msgs::msg::String>(topic, qos);
  }

  void forward(const geometry_msgs::msg::Twist & twist)
  {
    if (!locked_) {
      cmd_pub_->publish(twist);
    }
  }

  bool locked_{false};
  rclcpp::QoS lock_qos_;
  rclcpp::Subscription<geometry_msgs::msg::Twist>::SharedPtr joy_sub_;
  rclcpp::Subscription<geometry_msgs::msg::Twist>::SharedPtr nav_sub_;
  rclcpp::Subscription<std_msgs::msg::Bool>::SharedPtr lock_sub_;
  rclcpp::Publisher<geometry_msgs::msg::Twist>::SharedPtr cmd_pub_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr status_pub_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr history_pub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<TeleopMux>());
  rclcpp::shutdown();
  return 0;
}
