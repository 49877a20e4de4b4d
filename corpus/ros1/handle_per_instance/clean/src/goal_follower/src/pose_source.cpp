// Publishes the robot's pose in the world frame on "pose" and in the local frame on
// "local_pose", and logs the goals it gets back.
#include <geometry_msgs/PoseStamped.h>
#include <ros/ros.h>

void onGoal(const geometry_msgs::PoseStamped::ConstPtr& goal) {
  ROS_INFO_THROTTLE(5.0, "goal at x=%.2f", goal->pose.position.x);
}

int main(int argc, char** argv) {
  ros::init(argc, argv, "pose_source");
  ros::NodeHandle nh;
  ros::Publisher world = nh.advertise<geometry_msgs::PoseStamped>("pose", 1);
  ros::Publisher local = nh.advertise<geometry_msgs::PoseStamped>("local_pose", 1);
  ros::Subscriber world_goal = nh.subscribe("goal", 1, onGoal);
  ros::Subscriber local_goal = nh.subscribe("local_goal", 1, onGoal);
  ros::Rate rate(5.0);
  while (ros::ok()) {
    geometry_msgs::PoseStamped pose;
    pose.header.stamp = ros::Time::now();
    world.publish(pose);
    local.publish(pose);
    ros::spinOnce();
    rate.sleep();
  }
  return 0;
}
