// Grabs frames at 30 Hz and publishes them as sensor data.
#include <chrono>

#include "rclcpp/rclcpp.hpp"
#include "rclcpp_components/register_node_macro.hpp"
#include "sensor_msgs/msg/image.hpp"

namespace camera_pipeline
{

class CameraDriver : public rclcpp::Node
{
public:
  explicit CameraDriver(const rclcpp::NodeOptions & options)
  : Node("camera_driver", options)
  {
    image_pub_ = create_publisher<sensor_msgs::msg::Image>("image_raw", rclcpp::SensorDataQoS());
    timer_ = create_wall_timer(std::chrono::milliseconds(33), [this]() {grab();});
  }

private:
  void grab()
  {
    auto frame = std::make_unique<sensor_msgs::msg::Image>();
    frame->header.stamp = now();
    image_pub_->publish(std::move(frame));
  }

  rclcpp::Publisher<sensor_msgs::msg::Image>::SharedPtr image_pub_;
  rclcpp::TimerBase::SharedPtr timer_;
};

}  // namespace camera_pipeline

RCLCPP_COMPONENTS_REGISTER_NODE(camera_pipeline::CameraDriver)
