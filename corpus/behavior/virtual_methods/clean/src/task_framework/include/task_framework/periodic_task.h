// A task that runs on a timer: every tick publishes a heartbeat, then, when the derived task says
// it is ready, runs one step of it.
#pragma once

#include <ros/ros.h>
#include <std_msgs/String.h>

#include <string>

namespace task_framework {

class PeriodicTask {
 public:
  PeriodicTask(ros::NodeHandle& nh, double period) : pnh_("~") {
    heartbeat_pub_ = pnh_.advertise<std_msgs::String>("heartbeat", 1);
    timer_ = nh.createTimer(ros::Duration(period), &PeriodicTask::tick, this);
  }
  virtual ~PeriodicTask() = default;

 protected:
  virtual bool ready() const { return true; }
  virtual void step() = 0;
  virtual std::string name() const { return "task"; }

  ros::NodeHandle pnh_;

 private:
  void tick(const ros::TimerEvent&) {
    std_msgs::String beat;
    beat.data = name();
    heartbeat_pub_.publish(beat);
    if (!ready()) {
      return;
    }
    step();
  }

  ros::Publisher heartbeat_pub_;
  ros::Timer timer_;
};

}  // namespace task_framework
