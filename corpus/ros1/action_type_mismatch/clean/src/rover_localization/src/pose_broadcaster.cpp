// Broadcasts odom->base_link from odometry, the fixed base_link->laser mounting, and republishes
// the pose; a diagnostic task reports how fresh the odometry is.
#include <string>

#include <diagnostic_updater/diagnostic_updater.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/TransformStamped.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <tf2_ros/transform_broadcaster.h>

int main(int argc, char** argv) {
  ros::init(argc, argv, "pose_broadcaster");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  double laser_x;
  pnh.param("laser_x", laser_x, 0.25);

  tf2_ros::TransformBroadcaster broadcaster;
  tf2_ros::StaticTransformBroadcaster static_broadcaster;
  geometry_msgs::TransformStamped mount;
  mount.header.stamp = ros::Time::now();
  mount.header.frame_id = "base_link";
  mount.child_frame_id = "laser";
  mount.transform.translation.x = laser_x;
  mount.transform.rotation.w = 1.0;
  static_broadcaster.sendTransform(mount);

  ros::Publisher pose_pub = nh.advertise<geometry_msgs::PoseStamped>("pose", 10);
  ros::Time last_odom;
  ros::Subscriber odom_sub = nh.subscribe<nav_msgs::Odometry>(
      "odom", 10, [&](const nav_msgs::Odometry::ConstPtr& odom) {
        geometry_msgs::TransformStamped tf;
        tf.header = odom->header;
        tf.child_frame_id = odom->child_frame_id;
        tf.transform.translation.x = odom->pose.pose.position.x;
        tf.transform.translation.y = odom->pose.pose.position.y;
        tf.transform.translation.z = odom->pose.pose.position.z;
        tf.transform.rotation = odom->pose.pose.orientation;
        broadcaster.sendTransform(tf);
        geometry_msgs::PoseStamped pose;
        pose.header = odom->header;
        pose.pose = odom->pose.pose;
        pose_pub.publish(pose);
        last_odom = ros::Time::now();
      });

  diagnostic_updater::Updater updater;
  updater.setHardwareID("rover_odometry");
  updater.add("odometry age", [&](diagnostic_updater::DiagnosticStatusWrapper& stat) {
    const double age = last_odom.isZero() ? -1.0 : (ros::Time::now() - last_odom).toSec();
    if (age < 0.0 || age > 0.5)
      stat.summary(diagnostic_msgs::DiagnosticStatus::WARN, "odometry stale");
    else
      stat.summary(diagnostic_msgs::DiagnosticStatus::OK, "odometry fresh");
    stat.add("age", age);
  });
  ros::Timer diag_timer = nh.createTimer(ros::Duration(0.5), [&](const ros::TimerEvent&) { updater.update(); });
  ros::spin();
  return 0;
}
