// A node that creates its controllers as pluginlib classes its parameters name: the ports the
// controllers create are not in this file (each load is a hole of the node).
#include <memory>
#include <string>
#include <vector>

#include "geometry_msgs/msg/twist.hpp"
#include "pluginlib/class_loader.hpp"
#include "rclcpp/rclcpp.hpp"

namespace fleet
{
class Controller
{
public:
  virtual ~Controller() = default;
  virtual void configure(rclcpp::Node * node, const std::string & name) = 0;
};

class ControllerHost : public rclcpp::Node
{
public:
  ControllerHost()
  : Node("controller_host"), loader_("fleet", "fleet::Controller")
  {
    cmd_pub_ = create_publisher<geometry_msgs::msg::Twist>("cmd_vel", 10);
    auto ids = declare_parameter("controllers", std::vector<std::string>{"follow", "dock"});
    for (const auto & id : ids) {
      // loader_.createUniqueInstance(type) in a comment is no load
      auto type = declare_parameter(id + ".plugin", std::string("fleet::FollowController"));
      controllers_.push_back(loader_.createSharedInstance(type));
      controllers_.back()->configure(this, id);
    }
  }

private:
  pluginlib::ClassLoader<Controller> loader_;
  std::vector<std::shared_ptr<Controller>> controllers_;
  rclcpp::Publisher<geometry_msgs::msg::Twist>::SharedPtr cmd_pub_;
};
}  // namespace fleet

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<fleet::ControllerHost>());
  rclcpp::shutdown();
}
