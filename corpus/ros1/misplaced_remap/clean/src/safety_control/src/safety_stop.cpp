// Emergency-stop latch: engages on a proximity alert, releases after a hold time without one,
// and refuses to release until the sonar self-test has passed once.
#include <string>

#include <diagnostic_msgs/SelfTest.h>
#include <ros/ros.h>
#include <std_msgs/Bool.h>

class SafetyStop {
 public:
  explicit SafetyStop(ros::NodeHandle& nh) : nh_(nh), pnh_("~") {
    pnh_.param("hold_time", hold_time_, 2.0);
    alert_sub_ = nh_.subscribe("proximity_alert", 1, &SafetyStop::onAlert, this);
    estop_pub_ = nh_.advertise<std_msgs::Bool>("/estop", 1, true);
    timer_ = nh_.createTimer(ros::Duration(0.2), &SafetyStop::onTimer, this);
    publish();
  }

 private:
  void onAlert(const std_msgs::Bool::ConstPtr& alert) {
    if (alert->data) last_alert_ = ros::Time::now();
  }

  void onTimer(const ros::TimerEvent&) {
    if (!sonar_ok_) {
      diagnostic_msgs::SelfTest test;
      sonar_ok_ = ros::service::call("/sonar_array/self_test", test) && test.response.passed;
    }
    const bool stop = !sonar_ok_ || (!last_alert_.isZero() && (ros::Time::now() - last_alert_).toSec() < hold_time_);
    if (stop != engaged_) {
      engaged_ = stop;
      publish();
    }
  }

  void publish() {
    std_msgs::Bool msg;
    msg.data = engaged_;
    estop_pub_.publish(msg);
  }

  ros::NodeHandle nh_, pnh_;
  ros::Subscriber alert_sub_;
  ros::Publisher estop_pub_;
  ros::Timer timer_;
  ros::Time last_alert_;
  double hold_time_ = 2.0;
  bool sonar_ok_ = false, engaged_ = true;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "safety_stop");
  ros::NodeHandle nh;
  SafetyStop safety(nh);
  ros::spin();
  return 0;
}
