// Serves the Dock action and a private service that arms the charging contacts.
#include <memory>

#include "dock_interfaces/action/dock.hpp"
#include "rclcpp/rclcpp.hpp"
#include "rclcpp_action/rclcpp_action.hpp"
#include "std_srvs/srv/trigger.hpp"

using Dock = dock_interfaces::action::Dock;
using GoalHandleDock = rclcpp_action::ServerGoalHandle<Dock>;

class DockingServer : public rclcpp::Node
{
public:
  DockingServer()
  : Node("docking_server")
  {
    arm_service_ = create_service<std_srvs::srv::Trigger>(
      "~/arm_charger",
      [this](const std::shared_ptr<std_srvs::srv::Trigger::Request>,
      std::shared_ptr<std_srvs::srv::Trigger::Response> response) {
        armed_ = true;
        response->success = true;
      });
    action_server_ = rclcpp_action::create_server<Dock>(
      this, "dock",
      [](const rclcpp_action::GoalUUID &, std::shared_ptr<const Dock::Goal>) {
        return rclcpp_action::GoalResponse::ACCEPT_AND_EXECUTE;
      },
      [](const std::shared_ptr<GoalHandleDock>) {return rclcpp_action::CancelResponse::ACCEPT;},
      [this](const std::shared_ptr<GoalHandleDock> goal) {execute(goal);});
  }

private:
  void execute(const std::shared_ptr<GoalHandleDock> goal)
  {
    auto result = std::make_shared<Dock::Result>();
    result->docked = armed_;
    goal->succeed(result);
  }

  bool armed_ = false;
  rclcpp::Service<std_srvs::srv::Trigger>::SharedPtr arm_service_;
  rclcpp_action::Server<Dock>::SharedPtr action_server_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<DockingServer>());
  rclcpp::shutdown();
  return 0;
}
