// Coverage planner: sweeps the free cells of the costmap in boustrophedon order. The plan is
// recomputed on a 5 Hz timer once a costmap has arrived; progress is reported at 2 Hz regardless.
#include <geometry_msgs/PoseStamped.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <std_msgs/Float32.h>

class CoveragePlanner {
 public:
  explicit CoveragePlanner(ros::NodeHandle& nh) {
    ros::NodeHandle pnh("~");
    plan_pub_ = nh.advertise<nav_msgs::Path>("coverage_plan", 1);
    progress_pub_ = pnh.advertise<std_msgs::Float32>("progress", 1);
    costmap_sub_ = nh.subscribe("costmap", 1, &CoveragePlanner::costmapCallback, this);
    plan_timer_ = nh.createTimer(ros::Duration(0.2), &CoveragePlanner::planTimer, this);
    progress_timer_ = nh.createTimer(ros::Duration(0.5), &CoveragePlanner::progressTimer, this);
  }

 private:
  void costmapCallback(const nav_msgs::OccupancyGrid::ConstPtr& msg) {
    costmap_ = *msg;
    map_received_ = true;
  }

  void planTimer(const ros::TimerEvent&) {
    if (!map_received_) {
      return;
    }
    nav_msgs::Path plan;
    plan.header.frame_id = costmap_.header.frame_id;
    plan.header.stamp = ros::Time::now();
    const unsigned width = costmap_.info.width;
    const unsigned height = costmap_.info.height;
    for (unsigned row = 0; row < height; ++row) {
      for (unsigned k = 0; k < width; ++k) {
        const unsigned col = (row % 2 == 0) ? k : width - 1 - k;
        const size_t cell = row * width + col;
        if (cell >= costmap_.data.size() || costmap_.data[cell] != 0) continue;
        geometry_msgs::PoseStamped pose;
        pose.header = plan.header;
        pose.pose.position.x = costmap_.info.origin.position.x + (col + 0.5) * costmap_.info.resolution;
        pose.pose.position.y = costmap_.info.origin.position.y + (row + 0.5) * costmap_.info.resolution;
        pose.pose.orientation.w = 1.0;
        plan.poses.push_back(pose);
      }
    }
    covered_ = plan.poses.empty() ? 0.0f : 1.0f / plan.poses.size();
    plan_pub_.publish(plan);
  }

  void progressTimer(const ros::TimerEvent&) {
    std_msgs::Float32 progress;
    progress.data = covered_;
    progress_pub_.publish(progress);
  }

  ros::Publisher plan_pub_;
  ros::Publisher progress_pub_;
  ros::Subscriber costmap_sub_;
  ros::Timer plan_timer_;
  ros::Timer progress_timer_;
  nav_msgs::OccupancyGrid costmap_;
  bool map_received_ = false;
  float covered_ = 0.0f;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "coverage_planner");
  ros::NodeHandle nh;
  CoveragePlanner planner(nh);
  ros::spin();
  return 0;
}
