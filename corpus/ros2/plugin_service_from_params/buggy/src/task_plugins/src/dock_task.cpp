// The docking task: serves start_docking on the node that loads it.
#include <memory>
#include <string>

#include "pluginlib/class_list_macros.hpp"
#include "rclcpp/rclcpp.hpp"
#include "std_srvs/srv/trigger.hpp"
#include "task_host/task.hpp"

namespace task_plugins
{
class DockTask : public task_host::Task
{
public:
  void initialize(const rclcpp::Node::SharedPtr & node, const std::string & name) override
  {
    name_ = name;
    service_ = node->create_service<std_srvs::srv::Trigger>(
      "start_docking",
      [this](const std::shared_ptr<std_srvs::srv::Trigger::Request>,
      std::shared_ptr<std_srvs::srv::Trigger::Response> response) {
        response->success = true;
        response->message = name_ + " started";
      });
  }

private:
  std::string name_;
  rclcpp::Service<std_srvs::srv::Trigger>::SharedPtr service_;
};
}  // namespace task_plugins

PLUGINLIB_EXPORT_CLASS(task_plugins::DockTask, task_host::Task)
