// Loads the tasks its parameters list (task_plugins: [id, ...], id.plugin: the class) and hands each
// its own node: the ports a task creates are this node's.
#include <memory>
#include <string>
#include <vector>

#include "pluginlib/class_loader.hpp"
#include "rclcpp/rclcpp.hpp"
#include "task_host/task.hpp"

class TaskServer : public rclcpp::Node
{
public:
  TaskServer()
  : Node("task_server"), loader_("task_host", "task_host::Task")
  {
  }

  void load_tasks()
  {
    auto ids = declare_parameter("task_plugins", std::vector<std::string>{});
    for (const auto & id : ids) {
      auto type = declare_parameter(id + ".plugin", std::string(""));
      tasks_.push_back(loader_.createSharedInstance(type));
      tasks_.back()->initialize(shared_from_this(), id);
    }
  }

private:
  pluginlib::ClassLoader<task_host::Task> loader_;
  std::vector<std::shared_ptr<task_host::Task>> tasks_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<TaskServer>();
  node->load_tasks();
  rclcpp::spin(node);
  rclcpp::shutdown();
  return 0;
}
