// A lift controller: services with 2- and 3-argument callbacks, a client, and an action server and
// client (rclcpp_action) with the callbacks as lambdas and member functions.
#include <functional>
#include <memory>
#include <thread>

#include "example_interfaces/action/fibonacci.hpp"
#include "rclcpp/rclcpp.hpp"
#include "rclcpp_action/rclcpp_action.hpp"
#include "std_srvs/srv/set_bool.hpp"
#include "std_srvs/srv/trigger.hpp"

using Fibonacci = example_interfaces::action::Fibonacci;
using GoalHandle = rclcpp_action::ServerGoalHandle<Fibonacci>;
using std::placeholders::_1;
using std::placeholders::_2;

class LiftController : public rclcpp::Node
{
public:
  LiftController()
  : Node("lift_controller")
  {
    enable_srv_ = this->create_service<std_srvs::srv::SetBool>(
      "enable", std::bind(&LiftController::on_enable, this, _1, _2));
    home_srv_ = create_service<std_srvs::srv::Trigger>(
      "~/home",
      [this](const std::shared_ptr<rmw_request_id_t>, const std::shared_ptr<std_srvs::srv::Trigger::Request>,
      std::shared_ptr<std_srvs::srv::Trigger::Response> response) {
        response->success = enabled_;
      });
    brake_client_ = create_client<std_srvs::srv::SetBool>("brake/engage");
    move_server_ = rclcpp_action::create_server<Fibonacci>(
      this, "move_steps",
      [](const rclcpp_action::GoalUUID &, std::shared_ptr<const Fibonacci::Goal> goal) {
        return goal->order > 0 ? rclcpp_action::GoalResponse::ACCEPT_AND_EXECUTE :
        rclcpp_action::GoalResponse::REJECT;
      },
      [](const std::shared_ptr<GoalHandle>) {return rclcpp_action::CancelResponse::ACCEPT;},
      std::bind(&LiftController::on_accepted, this, _1));
    calibration_client_ = rclcpp_action::create_client<Fibonacci>(this, "/calibration/sequence");
  }

private:
  void on_enable(
    const std::shared_ptr<std_srvs::srv::SetBool::Request> request,
    std::shared_ptr<std_srvs::srv::SetBool::Response> response)
  {
    enabled_ = request->data;
    response->success = true;
  }

  void on_accepted(const std::shared_ptr<GoalHandle> handle)
  {
    auto result = std::make_shared<Fibonacci::Result>();
    handle->succeed(result);
  }

  bool enabled_{false};
  rclcpp::Service<std_srvs::srv::SetBool>::SharedPtr enable_srv_;
  rclcpp::Service<std_srvs::srv::Trigger>::SharedPtr home_srv_;
  rclcpp::Client<std_srvs::srv::SetBool>::SharedPtr brake_client_;
  rclcpp_action::Server<Fibonacci>::SharedPtr move_server_;
  rclcpp_action::Client<Fibonacci>::SharedPtr calibration_client_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<LiftController>());
  rclcpp::shutdown();
  return 0;
}
