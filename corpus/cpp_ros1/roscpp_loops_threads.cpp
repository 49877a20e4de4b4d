// A base driver with every way of running periodically without a timer: a worker thread with
// for(;;) and std::this_thread::sleep_for, a do-while with ros::Duration::sleep, a loop whose
// rate is not constant, a loop with no sleep (period unknown), a lambda called in the main loop,
// a publish at start-up before spinning, and one in a function nothing in this file calls.
#include <chrono>
#include <thread>

#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <std_msgs/Empty.h>
#include <std_msgs/Float32.h>
#include <std_msgs/String.h>

using namespace std::chrono_literals;

ros::Publisher g_odom_pub;
ros::Publisher g_battery_pub;
ros::Publisher g_diag_pub;

void batteryWorker()
{
  for (;;) {
    std_msgs::Float32 level;
    level.data = 0.8f;
    g_battery_pub.publish(level);
    std::this_thread::sleep_for(500ms);
  }
}

void diagnosticsLoop(double hz)
{
  ros::Rate rate(hz);
  while (ros::ok()) {
    g_diag_pub.publish(std_msgs::String());
    rate.sleep();
  }
}

void readEncoders(ros::Publisher& ticks_pub)
{
  while (true) {
    ticks_pub.publish(std_msgs::Empty());
  }
}

void publishOnDemand(const ros::Publisher& pub) { pub.publish(std_msgs::String()); }

int main(int argc, char** argv)
{
  ros::init(argc, argv, "base_driver");
  ros::NodeHandle nh;
  g_odom_pub = nh.advertise<nav_msgs::Odometry>("odom", 10);
  g_battery_pub = nh.advertise<std_msgs::Float32>("battery", 1);
  g_diag_pub = nh.advertise<std_msgs::String>("driver_diagnostics", 1);
  ros::Publisher ticks_pub = nh.advertise<std_msgs::Empty>("ticks", 100);
  ros::Publisher ready_pub = nh.advertise<std_msgs::Empty>("ready", 1, true);
  ros::Publisher cmd_echo_pub = nh.advertise<geometry_msgs::Twist>("cmd_echo", 1);

  ready_pub.publish(std_msgs::Empty());
  std::thread battery(batteryWorker);
  std::thread diagnostics(diagnosticsLoop, nh.param("diagnostics_rate", 2.0));
  std::thread encoders(readEncoders, std::ref(ticks_pub));

  auto send_odom = [](double x) {
    nav_msgs::Odometry odom;
    odom.pose.pose.position.x = x;
    g_odom_pub.publish(odom);
  };
  double x = 0.0;
  do {
    x += 0.01;
    send_odom(x);
    ros::spinOnce();
    ros::Duration(0.02).sleep();
  } while (ros::ok());
  battery.join();
  return 0;
}
