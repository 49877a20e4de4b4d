// A docking controller switched by services: a SetBool service selects docking or undocking (an
// enum class member), a Trigger service stops; a 20 Hz timer steers according to the mode, only
// once a dock pose is known and while the contact list (a vector the contacts callback fills) is
// empty. The action server's accepted callback runs the homing in a thread with a loop rate.
#include <chrono>
#include <functional>
#include <memory>
#include <thread>
#include <vector>

#include "example_interfaces/action/fibonacci.hpp"
#include "geometry_msgs/msg/pose_stamped.hpp"
#include "geometry_msgs/msg/twist.hpp"
#include "rclcpp/rclcpp.hpp"
#include "rclcpp_action/rclcpp_action.hpp"
#include "std_msgs/msg/string.hpp"
#include "std_msgs/msg/u_int32.hpp"
#include "std_srvs/srv/set_bool.hpp"
#include "std_srvs/srv/trigger.hpp"

using namespace std::chrono_literals;
using Fibonacci = example_interfaces::action::Fibonacci;
using GoalHandle = rclcpp_action::ServerGoalHandle<Fibonacci>;

enum class DockMode { kStopped, kDocking, kUndocking };

class DockController : public rclcpp::Node
{
public:
  DockController()
  : Node("dock_controller")
  {
    cmd_pub_ = create_publisher<geometry_msgs::msg::Twist>("cmd_vel", 10);
    mode_pub_ = create_publisher<std_msgs::msg::String>("~/mode", rclcpp::QoS(1).transient_local());
    progress_pub_ = create_publisher<std_msgs::msg::UInt32>("~/homing_progress", 10);
    dock_sub_ = create_subscription<geometry_msgs::msg::PoseStamped>(
      "dock_pose", 1, [this](geometry_msgs::msg::PoseStamped::SharedPtr msg) {dock_pose_ = msg;});
    contacts_sub_ = create_subscription<std_msgs::msg::String>(
      "contacts", 10, std::bind(&DockController::on_contact, this, std::placeholders::_1));
    select_srv_ = create_service<std_srvs::srv::SetBool>(
      "~/dock",
      [this](const std::shared_ptr<std_srvs::srv::SetBool::Request> request,
      std::shared_ptr<std_srvs::srv::SetBool::Response> response) {
        mode_ = request->data ? DockMode::kDocking : DockMode::kUndocking;
        announce(request->data ? "docking" : "undocking");
        response->success = true;
      });
    stop_srv_ = create_service<std_srvs::srv::Trigger>(
      "~/stop",
      [this](const std::shared_ptr<std_srvs::srv::Trigger::Request>,
      std::shared_ptr<std_srvs::srv::Trigger::Response> response) {
        mode_ = DockMode::kStopped;
        contacts_.clear();
        announce("stopped");
        response->success = true;
      });
    home_server_ = rclcpp_action::create_server<Fibonacci>(
      this, "home",
      [](const rclcpp_action::GoalUUID &, std::shared_ptr<const Fibonacci::Goal>) {
        return rclcpp_action::GoalResponse::ACCEPT_AND_EXECUTE;
      },
      [](const std::shared_ptr<GoalHandle>) {return rclcpp_action::CancelResponse::ACCEPT;},
      [this](const std::shared_ptr<GoalHandle> handle) {
        std::thread{std::bind(&DockController::home, this, std::placeholders::_1), handle}.detach();
      });
    timer_ = create_wall_timer(50ms, std::bind(&DockController::steer, this));
  }

private:
  void on_contact(const std_msgs::msg::String::SharedPtr msg) {contacts_.push_back(msg->data);}

  void announce(const char * mode)
  {
    std_msgs::msg::String text;
    text.data = mode;
    mode_pub_->publish(text);
  }

  void home(const std::shared_ptr<GoalHandle> handle)
  {
    rclcpp::Rate rate(4);
    for (uint32_t step = 0; step < 8 && rclcpp::ok(); ++step) {
      std_msgs::msg::UInt32 progress;
      progress.data = step;
      progress_pub_->publish(progress);
      rate.sleep();
    }
    handle->succeed(std::make_shared<Fibonacci::Result>());
  }

  void steer()
  {
    if (dock_pose_ == nullptr || !contacts_.empty()) {
      return;
    }
    geometry_msgs::msg::Twist cmd;
    if (mode_ == DockMode::kDocking) {
      cmd.linear.x = 0.1;
      cmd_pub_->publish(cmd);
    } else if (mode_ == DockMode::kUndocking) {
      cmd.linear.x = -0.1;
      cmd_pub_->publish(cmd);
    }
  }

  rclcpp::Publisher<geometry_msgs::msg::Twist>::SharedPtr cmd_pub_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr mode_pub_;
  rclcpp::Publisher<std_msgs::msg::UInt32>::SharedPtr progress_pub_;
  rclcpp::Subscription<geometry_msgs::msg::PoseStamped>::SharedPtr dock_sub_;
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr contacts_sub_;
  rclcpp::Service<std_srvs::srv::SetBool>::SharedPtr select_srv_;
  rclcpp::Service<std_srvs::srv::Trigger>::SharedPtr stop_srv_;
  rclcpp_action::Server<Fibonacci>::SharedPtr home_server_;
  rclcpp::TimerBase::SharedPtr timer_;
  geometry_msgs::msg::PoseStamped::SharedPtr dock_pose_;
  std::vector<std::string> contacts_;
  DockMode mode_{DockMode::kStopped};
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<DockController>());
  rclcpp::shutdown();
  return 0;
}
