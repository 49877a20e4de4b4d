// archlog stand-in for tf2_ros (ROS 2): broadcasters, listener and buffer, under the real names.
#ifndef ARCHLOG_ROS2_TF2_ROS_HPP_
#define ARCHLOG_ROS2_TF2_ROS_HPP_

#include "archlog_ros2/rclcpp.hpp"
#include "archlog_ros2/tf2.hpp"
#include "geometry_msgs/msg/transform_stamped.hpp"
#include "tf2_msgs/msg/tf_message.hpp"


namespace tf2_ros
{
class CreateTimerInterface
{
public:
  using SharedPtr = std::shared_ptr<CreateTimerInterface>;
  virtual ~CreateTimerInterface();
};
class CreateTimerROS : public CreateTimerInterface
{
public:
  CreateTimerROS(
    rclcpp::node_interfaces::NodeBaseInterface::SharedPtr node_base,
    rclcpp::node_interfaces::NodeTimersInterface::SharedPtr node_timers,
    rclcpp::CallbackGroup::SharedPtr callback_group = nullptr);
};
tf2::TimePoint fromMsg(const builtin_interfaces::msg::Time & time_msg);
builtin_interfaces::msg::Time toMsg(const tf2::TimePoint & t);
tf2::TimePoint fromRclcpp(const rclcpp::Time & time);
rclcpp::Time toRclcpp(const tf2::TimePoint & time);

class Buffer
{
public:
  using SharedPtr = std::shared_ptr<Buffer>;
  Buffer(
    rclcpp::Clock::SharedPtr clock, tf2::Duration cache_time = tf2::Duration(std::chrono::seconds(10)),
    rclcpp::Node::SharedPtr node = rclcpp::Node::SharedPtr());
  geometry_msgs::msg::TransformStamped lookupTransform(
    const std::string & target_frame, const std::string & source_frame, const tf2::TimePoint & time,
    const tf2::Duration timeout = tf2::Duration::zero()) const;
  geometry_msgs::msg::TransformStamped lookupTransform(
    const std::string & target_frame, const std::string & source_frame, const rclcpp::Time & time,
    const rclcpp::Duration timeout = rclcpp::Duration::from_nanoseconds(0)) const;
  geometry_msgs::msg::TransformStamped lookupTransform(
    const std::string & target_frame, const tf2::TimePoint & target_time, const std::string & source_frame,
    const tf2::TimePoint & source_time, const std::string & fixed_frame,
    const tf2::Duration timeout = tf2::Duration::zero()) const;
  bool canTransform(
    const std::string & target_frame, const std::string & source_frame, const tf2::TimePoint & target_time,
    const tf2::Duration timeout = tf2::Duration::zero(), std::string * errstr = nullptr) const;
  bool canTransform(
    const std::string & target_frame, const std::string & source_frame, const rclcpp::Time & time,
    const rclcpp::Duration timeout = rclcpp::Duration::from_nanoseconds(0), std::string * errstr = nullptr) const;
  template<class T>
  T & transform(
    const T & in, T & out, const std::string & target_frame,
    tf2::Duration timeout = tf2::Duration::zero()) const;
  template<class T>
  T transform(const T & in, const std::string & target_frame, tf2::Duration timeout = tf2::Duration::zero()) const;
  void setCreateTimerInterface(CreateTimerInterface::SharedPtr create_timer_interface);
  void setUsingDedicatedThread(bool value);
  bool setTransform(
    const geometry_msgs::msg::TransformStamped & transform, const std::string & authority,
    bool is_static = false);
  std::string allFramesAsString() const;
  std::string allFramesAsYAML() const;
};

class TransformListener
{
public:
  explicit TransformListener(tf2::BufferCore & buffer, bool spin_thread = true);
  explicit TransformListener(Buffer & buffer, bool spin_thread = true);
  template<class NodeT>
  TransformListener(Buffer & buffer, NodeT && node, bool spin_thread = true,
    const rclcpp::QoS & qos = rclcpp::QoS(100), const rclcpp::QoS & static_qos = rclcpp::QoS(100).transient_local());
  virtual ~TransformListener();
};

class TransformBroadcaster
{
public:
  template<class NodeT>
  TransformBroadcaster(NodeT && node, const rclcpp::QoS & qos = rclcpp::QoS(100),
    const rclcpp::PublisherOptions & options = rclcpp::PublisherOptions());
  void sendTransform(const geometry_msgs::msg::TransformStamped & transform);
  void sendTransform(const std::vector<geometry_msgs::msg::TransformStamped> & transforms);
};

class StaticTransformBroadcaster
{
public:
  template<class NodeT>
  StaticTransformBroadcaster(NodeT && node, const rclcpp::QoS & qos = rclcpp::QoS(1).transient_local(),
    const rclcpp::PublisherOptions & options = rclcpp::PublisherOptions());
  void sendTransform(const geometry_msgs::msg::TransformStamped & transform);
  void sendTransform(const std::vector<geometry_msgs::msg::TransformStamped> & transforms);
};

class MessageFilterBase
{
public:
  virtual ~MessageFilterBase();
  virtual void clear() = 0;
  virtual void setTargetFrame(const std::string & target_frame) = 0;
  virtual void setTolerance(const rclcpp::Duration & tolerance) = 0;
};

template<class M, class BufferT = tf2_ros::Buffer>
class MessageFilter : public MessageFilterBase
{
public:
  using MConstPtr = std::shared_ptr<const M>;
  template<class F, class TimeRepT = double, class TimeT = std::ratio<1>>
  MessageFilter(
    F & f, BufferT & buffer, const std::string & target_frame, uint32_t queue_size,
    const rclcpp::node_interfaces::NodeLoggingInterface::SharedPtr & node_logging,
    const rclcpp::node_interfaces::NodeClockInterface::SharedPtr & node_clock,
    std::chrono::duration<TimeRepT, TimeT> buffer_timeout = std::chrono::duration<TimeRepT, TimeT>::max());
  template<class NodeT, class TimeRepT = double, class TimeT = std::ratio<1>>
  MessageFilter(
    BufferT & buffer, const std::string & target_frame, uint32_t queue_size, const NodeT & node,
    std::chrono::duration<TimeRepT, TimeT> buffer_timeout = std::chrono::duration<TimeRepT, TimeT>::max());
  void clear() override;
  void setTargetFrame(const std::string & target_frame) override;
  void setTolerance(const rclcpp::Duration & tolerance) override;
  template<class F>
  void connectInput(F & f);
  template<typename C>
  void registerCallback(const C & callback);
};
}  // namespace tf2_ros

#endif  // ARCHLOG_ROS2_TF2_ROS_HPP_
