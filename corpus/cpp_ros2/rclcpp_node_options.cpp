// Built-in ports chosen by NodeOptions: the logger services on, the parameter services and rosout
// off (a setter given false that would add a group, or true that would remove one, changes nothing).
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"

class Chatter : public rclcpp::Node
{
public:
  Chatter()
  : Node(
      "chatter",
      rclcpp::NodeOptions().enable_logger_service(true).start_parameter_services(false).enable_rosout(false)
      .use_intra_process_comms(false).start_parameter_event_publisher(true))
  {
    pub_ = create_publisher<std_msgs::msg::String>("chatter", 10);
  }

private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Chatter>());
  rclcpp::shutdown();
  return 0;
}
