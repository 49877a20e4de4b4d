// A coverage planner whose timer publishes a plan only once it is enabled (a flag set by a
// callback), has a map (a shared pointer set by the map callback, reset on request) and has a
// non-empty frontier; a second timer publishes its progress unconditionally.
#include <memory>
#include <vector>

#include <geometry_msgs/Point.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <std_msgs/Bool.h>
#include <std_msgs/Empty.h>
#include <std_msgs/Float32.h>

class CoveragePlanner
{
public:
  explicit CoveragePlanner(ros::NodeHandle& nh) : enabled_(false)
  {
    plan_pub_ = nh.advertise<nav_msgs::Path>("coverage_plan", 1);
    progress_pub_ = nh.advertise<std_msgs::Float32>("progress", 1);
    map_sub_ = nh.subscribe("map", 1, &CoveragePlanner::mapCallback, this);
    enable_sub_ = nh.subscribe("enable", 1, &CoveragePlanner::enableCallback, this);
    reset_sub_ = nh.subscribe("reset", 1, &CoveragePlanner::resetCallback, this);
    plan_timer_ = nh.createTimer(ros::Duration(0.2), &CoveragePlanner::planTimer, this);
    progress_timer_ = nh.createTimer(ros::Rate(2.0), &CoveragePlanner::progressTimer, this);
  }

private:
  void mapCallback(const nav_msgs::OccupancyGrid::ConstPtr& msg)
  {
    map_ = msg;
    frontier_.clear();
    for (size_t i = 0; i < msg->data.size(); i += 16) {
      if (msg->data[i] == -1) {
        geometry_msgs::Point cell;
        cell.x = static_cast<double>(i % msg->info.width);
        cell.y = static_cast<double>(i / msg->info.width);
        frontier_.push_back(cell);
      }
    }
  }

  void enableCallback(const std_msgs::Bool::ConstPtr& msg) { enabled_ = msg->data; }

  void resetCallback(const std_msgs::Empty::ConstPtr&)
  {
    map_.reset();
    enabled_ = false;
  }

  void planTimer(const ros::TimerEvent&)
  {
    if (!enabled_ || map_ == nullptr) {
      return;
    }
    if (frontier_.empty()) {
      return;
    }
    nav_msgs::Path plan;
    plan.header.frame_id = map_->header.frame_id;
    for (const auto& cell : frontier_) {
      geometry_msgs::PoseStamped pose;
      pose.pose.position = cell;
      plan.poses.push_back(pose);
    }
    plan_pub_.publish(plan);
  }

  void progressTimer(const ros::TimerEvent&)
  {
    std_msgs::Float32 progress;
    progress.data = frontier_.empty() ? 1.0f : 0.0f;
    progress_pub_.publish(progress);
  }

  ros::Publisher plan_pub_;
  ros::Publisher progress_pub_;
  ros::Subscriber map_sub_;
  ros::Subscriber enable_sub_;
  ros::Subscriber reset_sub_;
  ros::Timer plan_timer_;
  ros::Timer progress_timer_;
  nav_msgs::OccupancyGrid::ConstPtr map_;
  std::vector<geometry_msgs::Point> frontier_;
  bool enabled_;
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "coverage_planner");
  ros::NodeHandle nh;
  CoveragePlanner planner(nh);
  ros::spin();
  return 0;
}
