// A library the executable links (target_link_libraries): a broadcaster, a listener and stages.
#pragma once
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <string>

namespace kit
{
class Broadcaster
{
public:
  Broadcaster();
  void send(const std::string& text);

private:
  ros::NodeHandle nh_;
  ros::Publisher pub_;
};

class Listener
{
public:
  explicit Listener(ros::NodeHandle nh = ros::NodeHandle());

private:
  ros::Subscriber sub_;
  void heard(const std_msgs::String::ConstPtr& msg);
};

class Stage
{
public:
  virtual ~Stage() = default;
  virtual void start(ros::NodeHandle& nh) = 0;
};

class Reporter : public Stage
{
public:
  void start(ros::NodeHandle& nh) override;

private:
  ros::Publisher pub_;
};

class Auditor : public Stage
{
public:
  void start(ros::NodeHandle& nh) override;

private:
  ros::Publisher pub_;
};
}  // namespace kit
