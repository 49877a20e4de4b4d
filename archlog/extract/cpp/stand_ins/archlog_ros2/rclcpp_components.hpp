// archlog stand-in for rclcpp_components (ROS 2): the registration macro and node factories.
#ifndef ARCHLOG_ROS2_RCLCPP_COMPONENTS_HPP_
#define ARCHLOG_ROS2_RCLCPP_COMPONENTS_HPP_

#include <type_traits>

#include "archlog_ros2/rclcpp.hpp"

namespace rclcpp_components
{
class NodeInstanceWrapper
{
public:
  std::shared_ptr<void> get_node_instance() const;
  rclcpp::node_interfaces::NodeBaseInterface::SharedPtr get_node_base_interface();
};
class NodeFactory
{
public:
  virtual ~NodeFactory();
  virtual NodeInstanceWrapper create_node_instance(const rclcpp::NodeOptions & options) = 0;
};
template<typename NodeT>
class NodeFactoryTemplate : public NodeFactory
{
public:
  NodeInstanceWrapper create_node_instance(const rclcpp::NodeOptions & options) override;
};
}  // namespace rclcpp_components

#define RCLCPP_COMPONENTS_REGISTER_NODE(NodeClass) \
  static_assert(std::is_class<NodeClass>::value, "a component is a class");

#endif  // ARCHLOG_ROS2_RCLCPP_COMPONENTS_HPP_
