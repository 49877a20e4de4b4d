// A camera calibration node using the ROS 2 libraries built on rclcpp: tf2_ros broadcasters and
// a listener, image_transport (free functions and ImageTransport), message_filters with a
// synchronizer, and diagnostic_updater.
#include <memory>

#include "diagnostic_updater/diagnostic_updater.hpp"
#include "geometry_msgs/msg/transform_stamped.hpp"
#include "image_transport/image_transport.hpp"
#include "message_filters/subscriber.h"
#include "message_filters/sync_policies/approximate_time.h"
#include "message_filters/synchronizer.h"
#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/camera_info.hpp"
#include "sensor_msgs/msg/image.hpp"
#include "tf2_ros/buffer.h"
#include "tf2_ros/static_transform_broadcaster.h"
#include "tf2_ros/transform_broadcaster.h"
#include "tf2_ros/transform_listener.h"

using ImageSync = message_filters::sync_policies::ApproximateTime<sensor_msgs::msg::Image, sensor_msgs::msg::Image>;

class Calibrator : public rclcpp::Node
{
public:
  Calibrator()
  : Node("calibrator"), updater_(this)
  {
    tf_broadcaster_ = std::make_unique<tf2_ros::TransformBroadcaster>(*this);
    static_broadcaster_ = std::make_shared<tf2_ros::StaticTransformBroadcaster>(this);
    tf_buffer_ = std::make_unique<tf2_ros::Buffer>(get_clock());
    tf_listener_ = std::make_shared<tf2_ros::TransformListener>(*tf_buffer_);

    overlay_pub_ = image_transport::create_publisher(this, "overlay", rmw_qos_profile_sensor_data);
    raw_sub_ = image_transport::create_subscription(
      this, "camera/image_raw",
      [this](const sensor_msgs::msg::Image::ConstSharedPtr & image) {frames_ += image->height > 0;}, "raw");
    rectified_pub_ = image_transport::create_camera_publisher(this, "rectified/image");

    left_.subscribe(this, "left/image_rect");
    right_.subscribe(this, "right/image_rect", rmw_qos_profile_sensor_data);
    sync_ = std::make_shared<message_filters::Synchronizer<ImageSync>>(ImageSync(10), left_, right_);

    updater_.setHardwareID("stereo-rig");
    updater_.add("frames", [this](diagnostic_updater::DiagnosticStatusWrapper & status) {
        status.summary(frames_ > 0 ? 0 : 1, "frame count");
      });
  }

  void start_preview()
  {
    preview_transport_ = std::make_shared<image_transport::ImageTransport>(shared_from_this());
    preview_pub_ = preview_transport_->advertise("preview", 1);
  }

private:
  int frames_{0};
  diagnostic_updater::Updater updater_;
  std::unique_ptr<tf2_ros::TransformBroadcaster> tf_broadcaster_;
  std::shared_ptr<tf2_ros::StaticTransformBroadcaster> static_broadcaster_;
  std::unique_ptr<tf2_ros::Buffer> tf_buffer_;
  std::shared_ptr<tf2_ros::TransformListener> tf_listener_;
  image_transport::Publisher overlay_pub_;
  image_transport::Subscriber raw_sub_;
  image_transport::CameraPublisher rectified_pub_;
  std::shared_ptr<image_transport::ImageTransport> preview_transport_;
  image_transport::Publisher preview_pub_;
  message_filters::Subscriber<sensor_msgs::msg::Image> left_;
  message_filters::Subscriber<sensor_msgs::msg::Image> right_;
  std::shared_ptr<message_filters::Synchronizer<ImageSync>> sync_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<Calibrator>();
  node->start_preview();
  rclcpp::spin(node);
  rclcpp::shutdown();
  return 0;
}
