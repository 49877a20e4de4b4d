// Finds objects in rectified frames.
#include "rclcpp/rclcpp.hpp"
#include "rclcpp_components/register_node_macro.hpp"
#include "sensor_msgs/msg/image.hpp"
#include "vision_msgs/msg/detection2_d_array.hpp"

namespace camera_pipeline
{

class Detector : public rclcpp::Node
{
public:
  explicit Detector(const rclcpp::NodeOptions & options)
  : Node("detector", options)
  {
    threshold_ = declare_parameter("threshold", 0.6);
    detections_pub_ = create_publisher<vision_msgs::msg::Detection2DArray>("detections", 10);
    image_sub_ = create_subscription<sensor_msgs::msg::Image>(
      "image_rect", rclcpp::SensorDataQoS(),
      std::bind(&Detector::on_image, this, std::placeholders::_1));
  }

private:
  void on_image(const sensor_msgs::msg::Image::ConstSharedPtr & image)
  {
    vision_msgs::msg::Detection2DArray detections;
    detections.header = image->header;
    detections_pub_->publish(detections);
  }

  double threshold_;
  rclcpp::Publisher<vision_msgs::msg::Detection2DArray>::SharedPtr detections_pub_;
  rclcpp::Subscription<sensor_msgs::msg::Image>::SharedPtr image_sub_;
};

}  // namespace camera_pipeline

RCLCPP_COMPONENTS_REGISTER_NODE(camera_pipeline::Detector)
