// A nodelet (kobuki's safety controller) whose ports are made by a helper object it hands its
// private handle to: onInit() calls the helper's init(), which is not a method of the nodelet
// class but is its code all the same (it was left out when only the exported class's methods
// were read). A member's type comes from a header that is not installed: clang marks the class
// invalid (its base is dropped), but keeps the calls in onInit(), and the handle's accessor is
// read from the tokens.
#include <geometry_msgs/Twist.h>
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.h>
#include <ros/ros.h>
#include <std_msgs/Empty.h>
#include <vendor_threads/thread.hpp>  // not installed: declares vendor::Thread

namespace guard
{
class Guard
{
public:
  explicit Guard(ros::NodeHandle& nh) : nh_(nh) {}

  bool init()
  {
    enable_sub_ = nh_.subscribe("enable", 10, &Guard::enableCb, this);
    cmd_pub_ = nh_.advertise<geometry_msgs::Twist>("cmd_vel", 10);
    return true;
  }

private:
  void enableCb(const std_msgs::EmptyConstPtr& msg) {}

  ros::NodeHandle nh_;
  ros::Subscriber enable_sub_;
  ros::Publisher cmd_pub_;
};

class GuardNodelet : public nodelet::Nodelet
{
public:
  void onInit() override
  {
    ros::NodeHandle nh = this->getPrivateNodeHandle();
    guard_.reset(new Guard(nh));
    if (guard_->init())
    {
      worker_.start(&GuardNodelet::spin, *this);
    }
  }

private:
  void spin() {}

  boost::shared_ptr<Guard> guard_;
  vendor::Thread worker_;
};
}  // namespace guard

PLUGINLIB_EXPORT_CLASS(guard::GuardNodelet, nodelet::Nodelet)
