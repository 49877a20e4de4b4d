// The interface every task plugin implements: the host gives it its node and the name it was listed under.
#ifndef TASK_HOST__TASK_HPP_
#define TASK_HOST__TASK_HPP_

#include <memory>
#include <string>

#include "rclcpp/rclcpp.hpp"

namespace task_host
{
class Task
{
public:
  virtual ~Task() = default;
  virtual void initialize(const rclcpp::Node::SharedPtr & node, const std::string & name) = 0;
};
}  // namespace task_host

#endif  // TASK_HOST__TASK_HPP_
