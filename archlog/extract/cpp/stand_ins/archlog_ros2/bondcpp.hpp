// archlog stand-in for bondcpp (ROS 2): the bond between two processes, under the real names.
#ifndef ARCHLOG_ROS2_BONDCPP_HPP_
#define ARCHLOG_ROS2_BONDCPP_HPP_

#include "archlog_ros2/rclcpp.hpp"
#include "archlog_ros2/rclcpp_lifecycle.hpp"

namespace bond
{
class Bond
{
public:
  using EventCallback = std::function<void (void)>;
  Bond(
    const std::string & topic, const std::string & id, rclcpp_lifecycle::LifecycleNode::SharedPtr nh,
    EventCallback on_broken = EventCallback(), EventCallback on_formed = EventCallback());
  Bond(
    const std::string & topic, const std::string & id, rclcpp::Node::SharedPtr nh,
    EventCallback on_broken = EventCallback(), EventCallback on_formed = EventCallback());
  ~Bond();
  void setupConnections();
  double getConnectTimeout() const;
  void setConnectTimeout(double dur);
  double getDisconnectTimeout() const;
  void setDisconnectTimeout(double dur);
  double getHeartbeatTimeout() const;
  void setHeartbeatTimeout(double dur);
  double getHeartbeatPeriod() const;
  void setHeartbeatPeriod(double dur);
  void start();
  void setFormedCallback(EventCallback on_formed);
  void setBrokenCallback(EventCallback on_broken);
  bool waitUntilFormed(rclcpp::Duration timeout = rclcpp::Duration(std::chrono::seconds(-1)));
  bool waitUntilBroken(rclcpp::Duration timeout = rclcpp::Duration(std::chrono::seconds(-1)));
  bool isBroken();
  void breakBond();
  std::string getTopic();
  std::string getId();
  std::string getInstanceId();
};
}  // namespace bond

#endif  // ARCHLOG_ROS2_BONDCPP_HPP_
