// A lift controller switched by services: raise/lower set an enum mode, the 20 Hz timer drives the
// motor according to the mode (a switch), only while homed (a flag the homing action sets when
// it succeeds); the action's execute callback reports its progress in a loop.
#include <actionlib/server/simple_action_server.h>
#include <boost/bind.hpp>
#include <nav_msgs/GetMapAction.h>
#include <ros/ros.h>
#include <roscpp/Empty.h>
#include <std_msgs/Float64.h>
#include <std_msgs/String.h>

class LiftController
{
public:
  enum class Mode { kIdle, kRaising, kLowering };

  explicit LiftController(ros::NodeHandle& nh)
    : home_server_(nh, "home", boost::bind(&LiftController::home, this, _1), false)
  {
    effort_pub_ = nh.advertise<std_msgs::Float64>("lift/effort", 1);
    mode_pub_ = nh.advertise<std_msgs::String>("lift/mode", 1, true);
    progress_pub_ = nh.advertise<std_msgs::Float64>("lift/homing_progress", 1);
    raise_srv_ = nh.advertiseService("lift/raise", &LiftController::raise, this);
    lower_srv_ = nh.advertiseService("lift/lower", &LiftController::lower, this);
    hold_srv_ = nh.advertiseService("lift/hold", &LiftController::hold, this);
    timer_ = nh.createTimer(ros::Duration(0.05), &LiftController::control, this);
    home_server_.start();
  }

private:
  bool raise(roscpp::Empty::Request&, roscpp::Empty::Response&)
  {
    setMode(Mode::kRaising, "raising");
    return true;
  }

  bool lower(roscpp::Empty::Request&, roscpp::Empty::Response&)
  {
    setMode(Mode::kLowering, "lowering");
    return true;
  }

  bool hold(roscpp::Empty::Request&, roscpp::Empty::Response&)
  {
    setMode(Mode::kIdle, "idle");
    return true;
  }

  void setMode(Mode mode, const std::string& name)
  {
    mode_ = mode;
    std_msgs::String text;
    text.data = name;
    mode_pub_.publish(text);
  }

  void home(const nav_msgs::GetMapGoalConstPtr&)
  {
    ros::Rate rate(5.0);
    for (int step = 0; step <= 10 && ros::ok(); ++step) {
      std_msgs::Float64 progress;
      progress.data = step / 10.0;
      progress_pub_.publish(progress);
      rate.sleep();
    }
    homed_ = true;
    home_server_.setSucceeded();
  }

  void control(const ros::TimerEvent&)
  {
    if (!homed_) {
      return;
    }
    std_msgs::Float64 effort;
    switch (mode_) {
      case Mode::kRaising:
        effort.data = 0.6;
        effort_pub_.publish(effort);
        break;
      case Mode::kLowering:
        effort.data = -0.4;
        effort_pub_.publish(effort);
        break;
      default:
        break;
    }
  }

  actionlib::SimpleActionServer<nav_msgs::GetMapAction> home_server_;
  ros::Publisher effort_pub_;
  ros::Publisher mode_pub_;
  ros::Publisher progress_pub_;
  ros::ServiceServer raise_srv_;
  ros::ServiceServer lower_srv_;
  ros::ServiceServer hold_srv_;
  ros::Timer timer_;
  Mode mode_ = Mode::kIdle;
  bool homed_ = false;
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "lift_controller");
  ros::NodeHandle nh;
  LiftController lift(nh);
  ros::spin();
  return 0;
}
