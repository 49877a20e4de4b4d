// archlog stand-in for diagnostic_updater (ROS 2): the updater that publishes /diagnostics.
#ifndef ARCHLOG_ROS2_DIAGNOSTIC_UPDATER_HPP_
#define ARCHLOG_ROS2_DIAGNOSTIC_UPDATER_HPP_

#include "archlog_ros2/rclcpp.hpp"
#include "diagnostic_msgs/msg/diagnostic_array.hpp"
#include "diagnostic_msgs/msg/diagnostic_status.hpp"

namespace diagnostic_updater
{
class DiagnosticStatusWrapper : public diagnostic_msgs::msg::DiagnosticStatus
{
public:
  void summary(unsigned char lvl, const std::string s);
  void summaryf(unsigned char lvl, const char * format, ...);
  void mergeSummary(unsigned char lvl, const std::string s);
  void clearSummary();
  template<class T>
  void add(const std::string & key, const T & val);
  void addf(const std::string & key, const char * format, ...);
  void clear();
};
class DiagnosticTask
{
public:
  explicit DiagnosticTask(const std::string name);
  virtual ~DiagnosticTask();
  const std::string & getName();
  virtual void run(DiagnosticStatusWrapper & stat) = 0;
};
class Updater
{
public:
  template<class NodeT>
  explicit Updater(NodeT node, double period = 1.0);
  void add(const std::string & name, std::function<void (DiagnosticStatusWrapper &)> f);
  template<class T>
  void add(const std::string name, T * c, void (T::* f)(DiagnosticStatusWrapper &));
  void add(DiagnosticTask & task);
  bool removeByName(const std::string name);
  void setHardwareID(const std::string & hwid);
  void setHardwareIDf(const char * format, ...);
  void force_update();
  void broadcast(unsigned char lvl, const std::string msg);
  double getPeriod() const;
  void setPeriod(double period);
};
}  // namespace diagnostic_updater

#endif  // ARCHLOG_ROS2_DIAGNOSTIC_UPDATER_HPP_
