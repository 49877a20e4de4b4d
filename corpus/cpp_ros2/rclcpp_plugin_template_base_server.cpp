// A mission plugin whose action server comes from its base class template: the base's configure()
// makes a job server object from (node, the name a virtual gives, ...); that object's constructor
// only keeps the node and the name, and its own configure() creates the rclcpp_action server with
// what it kept. The plugin passes the action type as the base's template argument and overrides the
// virtual with a literal. A progress reporter kept by the plugin the same way publishes on the topic
// its constructor was given, when it starts.
#include <memory>
#include <string>

#include "example_interfaces/action/fibonacci.hpp"
#include "pluginlib/class_list_macros.hpp"
#include "rclcpp/rclcpp.hpp"
#include "rclcpp_action/rclcpp_action.hpp"
#include "rclcpp_lifecycle/lifecycle_node.hpp"
#include "std_msgs/msg/string.hpp"

namespace missions
{

template<class ActionT>
class JobServer
{
public:
  JobServer(rclcpp_lifecycle::LifecycleNode::SharedPtr node, const std::string & job_name, int retries)
  : node_(node), job_name_(job_name), retries_(retries) {}

  bool configure()
  {
    server_ = rclcpp_action::create_server<ActionT>(
      node_, job_name_,
      [](const rclcpp_action::GoalUUID &, std::shared_ptr<const typename ActionT::Goal>) {
        return rclcpp_action::GoalResponse::ACCEPT_AND_EXECUTE;
      },
      [](std::shared_ptr<rclcpp_action::ServerGoalHandle<ActionT>>) {return rclcpp_action::CancelResponse::ACCEPT;},
      [](std::shared_ptr<rclcpp_action::ServerGoalHandle<ActionT>>) {});
    return true;
  }

private:
  rclcpp_lifecycle::LifecycleNode::SharedPtr node_;
  std::string job_name_;
  int retries_;
  typename rclcpp_action::Server<ActionT>::SharedPtr server_;
};

class ProgressReporter
{
public:
  ProgressReporter(rclcpp_lifecycle::LifecycleNode::SharedPtr node, const std::string & topic)
  {
    node_ = node;
    topic_ = topic;
  }

  void start()
  {
    publisher_ = node_->create_publisher<std_msgs::msg::String>(topic_, 5);
  }

private:
  rclcpp_lifecycle::LifecycleNode::SharedPtr node_;
  std::string topic_;
  rclcpp_lifecycle::LifecyclePublisher<std_msgs::msg::String>::SharedPtr publisher_;
};

class MissionBase
{
public:
  virtual ~MissionBase() = default;
  virtual bool configure(rclcpp_lifecycle::LifecycleNode::SharedPtr node) = 0;
};

template<class ActionT>
class JobMission : public MissionBase
{
public:
  bool configure(rclcpp_lifecycle::LifecycleNode::SharedPtr node) final
  {
    job_server_ = std::make_unique<JobServer<ActionT>>(node, getName(), 3);
    return job_server_->configure() && setup(node);
  }

  virtual std::string getName() = 0;

protected:
  virtual bool setup(rclcpp_lifecycle::LifecycleNode::SharedPtr node) = 0;

  std::unique_ptr<JobServer<ActionT>> job_server_;
};

class CountMission : public JobMission<example_interfaces::action::Fibonacci>
{
public:
  std::string getName() override {return std::string("count_up");}

protected:
  bool setup(rclcpp_lifecycle::LifecycleNode::SharedPtr node) override
  {
    reporter_ = std::make_unique<ProgressReporter>(node, "count_progress");
    reporter_->start();
    return true;
  }

  std::unique_ptr<ProgressReporter> reporter_;
};

}  // namespace missions

PLUGINLIB_EXPORT_CLASS(missions::CountMission, missions::MissionBase)
