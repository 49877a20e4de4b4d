// A dock manager whose action servers come from a library's factory: a node class's member
// template hands the name to a free function template, which makes a server object with
// make_shared; the object's public constructor delegates to one taking node interfaces, which keeps
// the name in a member and creates the rclcpp_action server with it. Each call of the member
// template is one server, named at that call. A non-template helper publishes on the topic it is
// given: each of its calls is one publisher too, and so is each object of a class whose constructor
// publishes on the topic it is given, with the type its parameter chooses.
#include <chrono>
#include <functional>
#include <memory>
#include <string>

#include "example_interfaces/action/fibonacci.hpp"
#include "geometry_msgs/msg/twist.hpp"
#include "geometry_msgs/msg/twist_stamped.hpp"
#include "rclcpp/rclcpp.hpp"
#include "rclcpp_action/rclcpp_action.hpp"
#include "rclcpp_lifecycle/lifecycle_node.hpp"
#include "std_msgs/msg/string.hpp"

namespace fleet
{

template<typename TaskT>
class TaskServer
{
public:
  using SharedPtr = std::shared_ptr<TaskServer<TaskT>>;
  using Work = std::function<void ()>;

  template<typename NodePtrT>
  TaskServer(NodePtrT node, const std::string & task_name, Work work, bool threaded = false)
  : TaskServer(node->get_node_base_interface(), node->get_node_clock_interface(),
      node->get_node_logging_interface(), node->get_node_waitables_interface(), task_name, work, threaded)
  {}

  TaskServer(
    rclcpp::node_interfaces::NodeBaseInterface::SharedPtr base,
    rclcpp::node_interfaces::NodeClockInterface::SharedPtr clock,
    rclcpp::node_interfaces::NodeLoggingInterface::SharedPtr logging,
    rclcpp::node_interfaces::NodeWaitablesInterface::SharedPtr waitables,
    const std::string & task_name, Work work, bool threaded = false)
  : label_(task_name), work_(work), threaded_(threaded)
  {
    server_ = rclcpp_action::create_server<TaskT>(
      base, clock, logging, waitables, label_,
      [](const rclcpp_action::GoalUUID &, std::shared_ptr<const typename TaskT::Goal>) {
        return rclcpp_action::GoalResponse::ACCEPT_AND_EXECUTE;
      },
      [](std::shared_ptr<rclcpp_action::ServerGoalHandle<TaskT>>) {return rclcpp_action::CancelResponse::ACCEPT;},
      [this](std::shared_ptr<rclcpp_action::ServerGoalHandle<TaskT>>) {work_();});
  }

private:
  std::string label_;
  Work work_;
  bool threaded_;
  typename rclcpp_action::Server<TaskT>::SharedPtr server_;
};

namespace factories
{
template<typename TaskT, typename NodePtrT>
typename TaskServer<TaskT>::SharedPtr make_task_server(
  const NodePtrT & node, const std::string & task_name, typename TaskServer<TaskT>::Work work,
  bool threaded = false)
{
  return std::make_shared<TaskServer<TaskT>>(node, task_name, work, threaded);
}
}  // namespace factories

class ManagedNode : public rclcpp_lifecycle::LifecycleNode
{
public:
  explicit ManagedNode(const std::string & name)
  : rclcpp_lifecycle::LifecycleNode(name) {}

  template<typename TaskT>
  typename TaskServer<TaskT>::SharedPtr add_task_server(
    const std::string & task_name, typename TaskServer<TaskT>::Work work, bool threaded = false)
  {
    return factories::make_task_server<TaskT>(shared_from_this(), task_name, work, threaded);
  }
};

class CommandOut
{
public:
  CommandOut(rclcpp_lifecycle::LifecycleNode * node, const std::string & topic)
  : topic_(topic)
  {
    stamped_mode_ = node->declare_parameter("stamped_commands", true);
    if (stamped_mode_) {
      stamped_ = node->create_publisher<geometry_msgs::msg::TwistStamped>(topic_, 1);
    } else {
      plain_ = node->create_publisher<geometry_msgs::msg::Twist>(topic_, 1);
    }
  }

private:
  std::string topic_;
  bool stamped_mode_;
  rclcpp_lifecycle::LifecyclePublisher<geometry_msgs::msg::TwistStamped>::SharedPtr stamped_;
  rclcpp_lifecycle::LifecyclePublisher<geometry_msgs::msg::Twist>::SharedPtr plain_;
};

}  // namespace fleet

using Fibonacci = example_interfaces::action::Fibonacci;

class DockManager : public fleet::ManagedNode
{
public:
  DockManager()
  : fleet::ManagedNode("dock_manager")
  {
    status_ = create_publisher<std_msgs::msg::String>("dock_status", 10);
  }

  void configure()
  {
    dock_server_ = add_task_server<Fibonacci>("dock_robot", [this]() {announce("docking");});
    undock_server_ = add_task_server<Fibonacci>("undock_robot", [this]() {announce("undocking");}, true);
    report("events/docked");
    report("events/undocked");
    drive_ = std::make_unique<fleet::CommandOut>(this, "dock_cmd_vel");
  }

private:
  void announce(const std::string & what)
  {
    std_msgs::msg::String message;
    message.data = what;
    status_->publish(message);
  }

  void report(const std::string & channel)
  {
    reporters_.push_back(create_publisher<std_msgs::msg::String>(channel, 1));
  }

  rclcpp_lifecycle::LifecyclePublisher<std_msgs::msg::String>::SharedPtr status_;
  std::vector<rclcpp_lifecycle::LifecyclePublisher<std_msgs::msg::String>::SharedPtr> reporters_;
  fleet::TaskServer<Fibonacci>::SharedPtr dock_server_;
  fleet::TaskServer<Fibonacci>::SharedPtr undock_server_;
  std::unique_ptr<fleet::CommandOut> drive_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<DockManager>();
  node->configure();
  rclcpp::spin(node->get_node_base_interface());
  rclcpp::shutdown();
  return 0;
}
