// Wheel odometry of one rover of the team. Each rover runs in its own namespace; its frames are
// prefixed with the namespace, tf_prefix style, without the leading slash ("rover1/odom").
#include <ros/ros.h>
#include <nav_msgs/Odometry.h>

int main(int argc, char** argv)
{
  ros::init(argc, argv, "wheel_odometry");
  ros::NodeHandle nh;
  std::string prefix = nh.getNamespace();
  if (!prefix.empty() && prefix[0] == '/')
    prefix.erase(0, 1);
  // the frame prefix reused for the topic: relative, so roscpp resolves it in the namespace again
  ros::Publisher odom_pub = nh.advertise<nav_msgs::Odometry>(prefix + "/odom", 10);
  ros::Rate rate(10.0);
  double x = 0.0;
  while (ros::ok()) {
    nav_msgs::Odometry odom;
    odom.header.stamp = ros::Time::now();
    odom.header.frame_id = prefix + "/odom";
    odom.child_frame_id = prefix + "/base_link";
    x += 0.01;
    odom.pose.pose.position.x = x;
    odom_pub.publish(odom);
    ros::spinOnce();
    rate.sleep();
  }
  return 0;
}
