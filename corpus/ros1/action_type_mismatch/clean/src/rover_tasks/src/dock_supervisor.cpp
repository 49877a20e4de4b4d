// Docking supervisor: requests the docking-area map through the map loader action, then drives
// the rover towards the dock using the odom->base_link transform.
#include <cmath>
#include <string>

#include <actionlib/client/simple_action_client.h>
#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/GetMapAction.h>
#include <ros/ros.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

namespace {
const std::string kMapAction = "load_dock_map";
}

int main(int argc, char** argv) {
  ros::init(argc, argv, "dock_supervisor");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  double dock_x, dock_y, gain;
  pnh.param("dock_x", dock_x, 3.0);
  pnh.param("dock_y", dock_y, 0.0);
  pnh.param("gain", gain, 0.5);

  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);
  actionlib::SimpleActionClient<nav_msgs::GetMapAction> map_client(kMapAction, true);
  ros::Publisher cmd_pub = nh.advertise<geometry_msgs::Twist>("cmd_vel", 10);

  bool requested = false;
  ros::Rate loop(10.0);
  while (ros::ok()) {
    if (!requested && map_client.isServerConnected()) {
      map_client.sendGoal(nav_msgs::GetMapGoal());
      requested = true;
    }
    geometry_msgs::Twist cmd;
    try {
      const geometry_msgs::TransformStamped pose = buffer.lookupTransform("odom", "base_link", ros::Time(0));
      const double dx = dock_x - pose.transform.translation.x;
      const double dy = dock_y - pose.transform.translation.y;
      const double yaw = 2.0 * std::atan2(pose.transform.rotation.z, pose.transform.rotation.w);
      const double distance = std::hypot(dx, dy);
      if (distance > 0.05) {
        cmd.linear.x = std::min(gain * distance, 0.4);
        cmd.angular.z = gain * std::remainder(std::atan2(dy, dx) - yaw, 2.0 * M_PI);
      }
    } catch (const tf2::TransformException& e) {
      ROS_DEBUG_THROTTLE(2.0, "waiting for odom->base_link: %s", e.what());
    }
    cmd_pub.publish(cmd);
    ros::spinOnce();
    loop.sleep();
  }
  return 0;
}
