// The controller's heartbeat: a counter every 100 ms while the control loop runs.
#include <chrono>
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/u_int32.hpp"

using namespace std::chrono_literals;

class Heartbeat : public rclcpp::Node
{
public:
  Heartbeat()
  : Node("heartbeat")
  {
    rclcpp::QoS qos(1);
    qos.reliable();
    pub_ = create_publisher<std_msgs::msg::UInt32>("heartbeat", qos);
    timer_ = create_wall_timer(100ms, [this]() {
        std_msgs::msg::UInt32 beat;
        beat.data = count_++;
        pub_->publish(beat);
      });
  }

private:
  uint32_t count_ = 0;
  rclcpp::Publisher<std_msgs::msg::UInt32>::SharedPtr pub_;
  rclcpp::TimerBase::SharedPtr timer_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Heartbeat>());
  rclcpp::shutdown();
  return 0;
}
