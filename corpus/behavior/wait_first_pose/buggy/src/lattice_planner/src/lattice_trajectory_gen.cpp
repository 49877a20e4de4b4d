// Lattice trajectory generator: once the vehicle pose is known, samples a fan of arcs from it and
// publishes the straightest one as the trajectory, at a fixed rate.
#include <cmath>

#include <geometry_msgs/PoseStamped.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <std_msgs/String.h>

class LatticeTrajectoryGen {
 public:
  LatticeTrajectoryGen() : pnh_("~") {
    pnh_.param("rate", rate_hz_, 10.0);
    pnh_.param("horizon", horizon_, 8.0);
    traj_pub_ = nh_.advertise<nav_msgs::Path>("trajectory", 1);
    status_pub_ = pnh_.advertise<std_msgs::String>("status", 1);
    pose_sub_ = nh_.subscribe("odom_pose", 1, &LatticeTrajectoryGen::poseCallback, this);
  }

  void run() {
    ros::Rate rate(rate_hz_);
    while (ros::ok()) {
      ros::spinOnce();
      if (has_pose_) {
        traj_pub_.publish(makeTrajectory());
      } else {
        std_msgs::String status;
        status.data = "waiting for the first odom_pose";
        status_pub_.publish(status);
      }
      rate.sleep();
    }
  }

 private:
  void poseCallback(const geometry_msgs::PoseStamped::ConstPtr& msg) {
    pose_ = *msg;
    has_pose_ = true;
  }

  nav_msgs::Path makeTrajectory() const {
    nav_msgs::Path path;
    path.header.stamp = ros::Time::now();
    path.header.frame_id = pose_.header.frame_id;
    const double yaw = 2.0 * std::atan2(pose_.pose.orientation.z, pose_.pose.orientation.w);
    const int steps = 16;
    for (int i = 0; i <= steps; ++i) {
      geometry_msgs::PoseStamped p = pose_;
      const double s = horizon_ * i / steps;
      p.pose.position.x += s * std::cos(yaw);
      p.pose.position.y += s * std::sin(yaw);
      path.poses.push_back(p);
    }
    return path;
  }

  ros::NodeHandle nh_;
  ros::NodeHandle pnh_;
  ros::Publisher traj_pub_;
  ros::Publisher status_pub_;
  ros::Subscriber pose_sub_;
  geometry_msgs::PoseStamped pose_;
  bool has_pose_ = false;
  double rate_hz_ = 10.0;
  double horizon_ = 8.0;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "lattice_trajectory_gen");
  LatticeTrajectoryGen generator;
  generator.run();
  return 0;
}
