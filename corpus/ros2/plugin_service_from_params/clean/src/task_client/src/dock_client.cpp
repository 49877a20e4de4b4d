// Asks the task server to start docking once it is up.
#include <chrono>
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "std_srvs/srv/trigger.hpp"

class DockClient : public rclcpp::Node
{
public:
  DockClient()
  : Node("dock_client")
  {
    client_ = create_client<std_srvs::srv::Trigger>("start_docking");
  }

  void request()
  {
    client_->wait_for_service();
    client_->async_send_request(std::make_shared<std_srvs::srv::Trigger::Request>());
  }

private:
  rclcpp::Client<std_srvs::srv::Trigger>::SharedPtr client_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<DockClient>();
  node->request();
  rclcpp::spin(node);
  rclcpp::shutdown();
  return 0;
}
