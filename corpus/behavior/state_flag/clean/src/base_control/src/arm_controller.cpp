// Motor arming: the drive motors get a current command only after the safety supervisor has
// enabled the base; the arming state itself is reported all the time.
#include <ros/ros.h>
#include <std_msgs/Bool.h>
#include <std_msgs/Float64.h>
#include <std_msgs/String.h>

namespace {
bool g_armed = false;
double g_hold_current = 0.4;
ros::Publisher g_motor_pub;
ros::Publisher g_state_pub;

void enableCallback(const std_msgs::Bool::ConstPtr& msg) {
  if (msg->data) {
    g_armed = true;
  }
}

void controlTick(const ros::TimerEvent&) {
  std_msgs::String state;
  state.data = g_armed ? "armed" : "disarmed";
  g_state_pub.publish(state);
  if (!g_armed) {
    return;
  }
  std_msgs::Float64 current;
  current.data = g_hold_current;
  g_motor_pub.publish(current);
}
}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "arm_controller");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  pnh.param("hold_current", g_hold_current, 0.4);
  g_motor_pub = nh.advertise<std_msgs::Float64>("motor_cmd", 1);
  g_state_pub = pnh.advertise<std_msgs::String>("state", 1);
  ros::Subscriber enable_sub = nh.subscribe("base_enable", 1, enableCallback);
  ros::Timer timer = nh.createTimer(ros::Duration(0.05), controlTick);
  ros::spin();
  return 0;
}
