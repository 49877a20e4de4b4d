// Classes of the executable whose methods are defined in relay.cpp and called from main.cpp.
#pragma once
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <string>

class Relay
{
public:
  Relay(ros::NodeHandle& nh, const std::string& topic, bool verbose);

private:
  ros::Subscriber sub_;
  ros::Publisher pub_, debug_;
  void forward(const std_msgs::String::ConstPtr& msg);
};

class Stage
{
public:
  virtual ~Stage() = default;
  virtual void setup(ros::NodeHandle& nh) = 0;
};

class Counter : public Stage
{
public:
  void setup(ros::NodeHandle& nh) override;

private:
  ros::Publisher pub_;
};
