// A mission plugin whose action server comes from its base class template: the base's configure()
// makes a job server object from (node, the name a virtual gives, ...); that object's constructor
// only keeps the node and the name, and its own configure() creates the rclcpp_action server with
// what it kept. The plugin passes the action type as the base's template argument and overrides the
// virtual with a literal. A progress reporter kept by the plugin the same way publishes on the topic
// its constructor was given, when it starts. A host node's method template makes a second job server
// for the base (a call written on an object: the free factory of the same name, which takes the
// node first, is not what runs).
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

namespace factory
{
template<class ActionT>
std::unique_ptr<JobServer<ActionT>> make_job(
  rclcpp_lifecycle::LifecycleNode::SharedPtr node, const std::string & job_name, int retries = 1)
{
  return std::make_unique<JobServer<ActionT>>(node, job_name, retries);
}
}  // namespace factory

class MissionNode : public rclcpp_lifecycle::LifecycleNode
{
public:
  MissionNode()
  : rclcpp_lifecycle::LifecycleNode("mission_host", rclcpp::NodeOptions()) {}

  template<class ActionT>
  std::unique_ptr<JobServer<ActionT>> make_job(const std::string & job_name, const std::string & owner = "")
  {
    (void)owner;
    return factory::make_job<ActionT>(shared_from_this(), job_name, 2);
  }
};

class MissionBase
{
public:
  virtual ~MissionBase() = default;
  virtual bool configure(rclcpp_lifecycle::LifecycleNode::SharedPtr node) = 0;
  virtual void audit(std::shared_ptr<MissionNode> host) = 0;
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

  void audit(std::shared_ptr<MissionNode> host) final
  {
    audit_server_ = host->make_job<ActionT>(auditName(), "auditor");
  }

  virtual std::string getName() = 0;
  virtual std::string auditName() = 0;

protected:
  virtual bool setup(rclcpp_lifecycle::LifecycleNode::SharedPtr node) = 0;

  std::unique_ptr<JobServer<ActionT>> job_server_;
  std::unique_ptr<JobServer<ActionT>> audit_server_;
};

class CountMission : public JobMission<example_interfaces::action::Fibonacci>
{
public:
  std::string getName() override {return std::string("count_up");}
  std::string auditName() override {return "count_audit";}

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
