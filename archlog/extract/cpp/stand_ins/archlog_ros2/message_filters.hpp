// archlog stand-in for message_filters (ROS 2): subscribers and synchronizers, under the real
// names.
#ifndef ARCHLOG_ROS2_MESSAGE_FILTERS_HPP_
#define ARCHLOG_ROS2_MESSAGE_FILTERS_HPP_

#include "archlog_ros2/rclcpp.hpp"

namespace message_filters
{
class Connection
{
public:
  void disconnect();
};
struct NullType
{
};
template<class M>
class SimpleFilter
{
public:
  template<typename C>
  Connection registerCallback(const C & callback);
  template<typename T>
  Connection registerCallback(void (T::* callback)(const std::shared_ptr<const M> &), T * t);
};
template<class M, class NodeType = rclcpp::Node>
class Subscriber : public SimpleFilter<M>
{
public:
  typedef std::shared_ptr<NodeType> NodePtr;
  Subscriber(
    NodePtr node, const std::string & topic, const rmw_qos_profile_t qos = rmw_qos_profile_default);
  Subscriber(
    NodeType * node, const std::string & topic, const rmw_qos_profile_t qos = rmw_qos_profile_default);
  Subscriber(
    NodePtr node, const std::string & topic, const rmw_qos_profile_t qos,
    rclcpp::SubscriptionOptions options);
  Subscriber(
    NodeType * node, const std::string & topic, const rmw_qos_profile_t qos,
    rclcpp::SubscriptionOptions options);
  Subscriber();
  void subscribe(NodePtr node, const std::string & topic, const rmw_qos_profile_t qos = rmw_qos_profile_default);
  void subscribe(NodeType * node, const std::string & topic, const rmw_qos_profile_t qos = rmw_qos_profile_default);
  void subscribe(
    NodeType * node, const std::string & topic, const rmw_qos_profile_t qos, rclcpp::SubscriptionOptions options);
  void unsubscribe();
  std::string getTopic() const;
};
template<class M>
class Cache : public SimpleFilter<M>
{
public:
  template<class F>
  Cache(F & f, unsigned int cache_size = 1);
  explicit Cache(unsigned int cache_size = 1);
  template<class F>
  void connectInput(F & f);
  void setCacheSize(unsigned int cache_size);
  std::shared_ptr<const M> getElemBeforeTime(const rclcpp::Time & time) const;
};
template<class Policy>
class Synchronizer : public Policy
{
public:
  template<class F0, class F1>
  Synchronizer(const Policy & policy, F0 & f0, F1 & f1);
  template<class F0, class F1, class F2>
  Synchronizer(const Policy & policy, F0 & f0, F1 & f1, F2 & f2);
  template<class F0, class F1, class F2, class F3>
  Synchronizer(const Policy & policy, F0 & f0, F1 & f1, F2 & f2, F3 & f3);
  template<class F0, class F1>
  void connectInput(F0 & f0, F1 & f1);
  template<typename C>
  Connection registerCallback(const C & callback);
  template<typename C, typename T>
  Connection registerCallback(const C & callback, T * t);
  void setAgePenalty(double age_penalty);
  void setMaxIntervalDuration(const rclcpp::Duration & max_interval_duration);
};
namespace sync_policies
{
template<typename M0, typename M1, typename M2 = NullType, typename M3 = NullType, typename M4 = NullType,
  typename M5 = NullType, typename M6 = NullType, typename M7 = NullType, typename M8 = NullType>
struct ApproximateTime
{
  ApproximateTime(uint32_t queue_size);  // NOLINT
  void setAgePenalty(double age_penalty);
  void setMaxIntervalDuration(const rclcpp::Duration & max_interval_duration);
};
template<typename M0, typename M1, typename M2 = NullType, typename M3 = NullType, typename M4 = NullType,
  typename M5 = NullType, typename M6 = NullType, typename M7 = NullType, typename M8 = NullType>
struct ExactTime
{
  ExactTime(uint32_t queue_size);  // NOLINT
};
}  // namespace sync_policies
template<class M0, class M1, class M2 = NullType, class M3 = NullType, class M4 = NullType,
  class M5 = NullType, class M6 = NullType, class M7 = NullType, class M8 = NullType>
class TimeSynchronizer
{
public:
  template<class F0, class F1>
  TimeSynchronizer(F0 & f0, F1 & f1, uint32_t queue_size);
  template<class F0, class F1, class F2>
  TimeSynchronizer(F0 & f0, F1 & f1, F2 & f2, uint32_t queue_size);
  template<typename C>
  Connection registerCallback(const C & callback);
};
}  // namespace message_filters

#endif  // ARCHLOG_ROS2_MESSAGE_FILTERS_HPP_
