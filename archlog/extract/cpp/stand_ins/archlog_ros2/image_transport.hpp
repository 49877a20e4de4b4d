// archlog stand-in for image_transport (ROS 2): publishers and subscribers of images, under the
// real names.
#ifndef ARCHLOG_ROS2_IMAGE_TRANSPORT_HPP_
#define ARCHLOG_ROS2_IMAGE_TRANSPORT_HPP_

#include "archlog_ros2/rclcpp.hpp"
#include "sensor_msgs/msg/camera_info.hpp"
#include "sensor_msgs/msg/image.hpp"

namespace image_transport
{
class Publisher
{
public:
  Publisher();
  size_t getNumSubscribers() const;
  std::string getTopic() const;
  void publish(const sensor_msgs::msg::Image & message) const;
  void publish(const sensor_msgs::msg::Image::ConstSharedPtr & message) const;
  void publish(sensor_msgs::msg::Image::UniquePtr message) const;
  void shutdown();
  operator void *() const;
};
class Subscriber
{
public:
  typedef std::function<void (const sensor_msgs::msg::Image::ConstSharedPtr &)> Callback;
  Subscriber();
  std::string getTopic() const;
  size_t getNumPublishers() const;
  void shutdown();
  operator void *() const;
};
class CameraPublisher
{
public:
  CameraPublisher();
  CameraPublisher(
    rclcpp::Node * node, const std::string & base_topic, rmw_qos_profile_t custom_qos = rmw_qos_profile_default,
    rclcpp::PublisherOptions pub_options = rclcpp::PublisherOptions());
  size_t getNumSubscribers() const;
  std::string getTopic() const;
  std::string getInfoTopic() const;
  void publish(const sensor_msgs::msg::Image & image, const sensor_msgs::msg::CameraInfo & info) const;
  void publish(
    const sensor_msgs::msg::Image::ConstSharedPtr & image,
    const sensor_msgs::msg::CameraInfo::ConstSharedPtr & info) const;
  void publish(sensor_msgs::msg::Image::UniquePtr image, sensor_msgs::msg::CameraInfo::UniquePtr info) const;
  void shutdown();
  operator void *() const;
};
class CameraSubscriber
{
public:
  typedef std::function<void (const sensor_msgs::msg::Image::ConstSharedPtr &,
      const sensor_msgs::msg::CameraInfo::ConstSharedPtr &)> Callback;
  CameraSubscriber();
  std::string getTopic() const;
  std::string getInfoTopic() const;
  size_t getNumPublishers() const;
  void shutdown();
  operator void *() const;
};
class TransportHints
{
public:
  TransportHints(
    const rclcpp::Node * node, const std::string & default_transport = "raw",
    const std::string & parameter_name = "image_transport");
  const std::string & getTransport() const;
};

Publisher create_publisher(
  rclcpp::Node * node, const std::string & base_topic, rmw_qos_profile_t custom_qos = rmw_qos_profile_default,
  rclcpp::PublisherOptions options = rclcpp::PublisherOptions());
Subscriber create_subscription(
  rclcpp::Node * node, const std::string & base_topic, const Subscriber::Callback & callback,
  const std::string & transport, rmw_qos_profile_t custom_qos = rmw_qos_profile_default,
  rclcpp::SubscriptionOptions options = rclcpp::SubscriptionOptions());
CameraPublisher create_camera_publisher(
  rclcpp::Node * node, const std::string & base_topic, rmw_qos_profile_t custom_qos = rmw_qos_profile_default,
  rclcpp::PublisherOptions pub_options = rclcpp::PublisherOptions());
CameraSubscriber create_camera_subscription(
  rclcpp::Node * node, const std::string & base_topic, const CameraSubscriber::Callback & callback,
  const std::string & transport, rmw_qos_profile_t custom_qos = rmw_qos_profile_default);

class ImageTransport
{
public:
  explicit ImageTransport(rclcpp::Node::SharedPtr node);
  Publisher advertise(const std::string & base_topic, uint32_t queue_size, bool latch = false);
  Publisher advertise(
    const std::string & base_topic, rmw_qos_profile_t custom_qos, rclcpp::PublisherOptions options = {});
  Subscriber subscribe(
    const std::string & base_topic, uint32_t queue_size, const Subscriber::Callback & callback,
    const std::shared_ptr<void> & tracked_object = {}, const TransportHints * transport_hints = nullptr,
    const rclcpp::SubscriptionOptions options = rclcpp::SubscriptionOptions());
  Subscriber subscribe(
    const std::string & base_topic, uint32_t queue_size,
    void (* fp)(const sensor_msgs::msg::Image::ConstSharedPtr &), const TransportHints * transport_hints = nullptr,
    const rclcpp::SubscriptionOptions options = rclcpp::SubscriptionOptions());
  template<class T>
  Subscriber subscribe(
    const std::string & base_topic, uint32_t queue_size,
    void (T::* fp)(const sensor_msgs::msg::Image::ConstSharedPtr &), T * obj,
    const TransportHints * transport_hints = nullptr,
    const rclcpp::SubscriptionOptions options = rclcpp::SubscriptionOptions());
  template<class T>
  Subscriber subscribe(
    const std::string & base_topic, uint32_t queue_size,
    void (T::* fp)(const sensor_msgs::msg::Image::ConstSharedPtr &), const std::shared_ptr<T> & obj,
    const TransportHints * transport_hints = nullptr,
    const rclcpp::SubscriptionOptions options = rclcpp::SubscriptionOptions());
  CameraPublisher advertiseCamera(const std::string & base_topic, uint32_t queue_size, bool latch = false);
  CameraSubscriber subscribeCamera(
    const std::string & base_topic, uint32_t queue_size, const CameraSubscriber::Callback & callback,
    const std::shared_ptr<void> & tracked_object = {}, const TransportHints * transport_hints = nullptr);
  template<class T>
  CameraSubscriber subscribeCamera(
    const std::string & base_topic, uint32_t queue_size,
    void (T::* fp)(const sensor_msgs::msg::Image::ConstSharedPtr &,
    const sensor_msgs::msg::CameraInfo::ConstSharedPtr &),
    T * obj, const TransportHints * transport_hints = nullptr);
  std::vector<std::string> getDeclaredTransports() const;
};
}  // namespace image_transport

#endif  // ARCHLOG_ROS2_IMAGE_TRANSPORT_HPP_
