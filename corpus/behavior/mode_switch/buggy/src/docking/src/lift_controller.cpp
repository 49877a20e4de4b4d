// Cart lift: a service switches the lift into raising mode; while raising, and once the robot is
// aligned under the cart (a dock pose has been seen), the lift motor is driven at 20 Hz.
#include <geometry_msgs/PoseStamped.h>
#include <ros/ros.h>
#include <roscpp/Empty.h>
#include <std_msgs/Float64.h>
#include <std_msgs/String.h>

enum class LiftMode { kIdle, kRaising };

class LiftController {
 public:
  explicit LiftController(ros::NodeHandle& nh) {
    command_pub_ = nh.advertise<std_msgs::Float64>("lift/command", 1);
    state_pub_ = nh.advertise<std_msgs::String>("lift/state", 1, true);
    dock_sub_ = nh.subscribe("dock_pose", 1, &LiftController::dockCallback, this);
    raise_srv_ = nh.advertiseService("lift/raise", &LiftController::raise, this);
  }

  void run() {
    ros::Rate rate(20.0);
    while (ros::ok()) {
      ros::spinOnce();
      if (mode_ == LiftMode::kRaising && aligned_) {
        std_msgs::Float64 effort;
        effort.data = 0.6;
        command_pub_.publish(effort);
      }
      rate.sleep();
    }
  }

 private:
  void dockCallback(const geometry_msgs::PoseStamped::ConstPtr&) { aligned_ = true; }

  bool raise(roscpp::Empty::Request&, roscpp::Empty::Response&) {
    mode_ = LiftMode::kRaising;
    std_msgs::String state;
    state.data = "raising";
    state_pub_.publish(state);
    return true;
  }

  ros::Publisher command_pub_;
  ros::Publisher state_pub_;
  ros::Subscriber dock_sub_;
  ros::ServiceServer raise_srv_;
  LiftMode mode_ = LiftMode::kIdle;
  bool aligned_ = false;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "lift_controller");
  ros::NodeHandle nh;
  LiftController lift(nh);
  lift.run();
  return 0;
}
