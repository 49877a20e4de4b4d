// Obstacle tracker: clusters the segmented points of each scan into obstacles (one pose per
// cluster), and reports how many it tracks at 1 Hz.
#include <cmath>

#include <geometry_msgs/PoseArray.h>
#include <ros/ros.h>
#include <sensor_msgs/PointCloud.h>
#include <std_msgs/Int32.h>

namespace obstacle_pipeline {

class ObstacleTracker {
 public:
  ObstacleTracker(ros::NodeHandle& nh, ros::NodeHandle& pnh) {
    pnh.param("cluster_gap", cluster_gap_, 0.3);
    obstacles_pub_ = nh.advertise<geometry_msgs::PoseArray>("obstacles", 1);
    count_pub_ = pnh.advertise<std_msgs::Int32>("track_count", 1);
    points_sub_ = nh.subscribe("scan_points", 1, &ObstacleTracker::pointsCallback, this);
    count_timer_ = nh.createTimer(ros::Duration(1.0), &ObstacleTracker::reportCount, this);
  }

 private:
  void pointsCallback(const sensor_msgs::PointCloud::ConstPtr& cloud) {
    geometry_msgs::PoseArray obstacles;
    obstacles.header = cloud->header;
    cluster(*cloud, obstacles);
    tracked_ = static_cast<int>(obstacles.poses.size());
    obstacles_pub_.publish(obstacles);
  }

  void cluster(const sensor_msgs::PointCloud& cloud, geometry_msgs::PoseArray& out) const {
    double sx = 0.0, sy = 0.0;
    int n = 0;
    for (size_t i = 0; i < cloud.points.size(); ++i) {
      const auto& p = cloud.points[i];
      if (n > 0 && std::hypot(p.x - sx / n, p.y - sy / n) > cluster_gap_) {
        out.poses.push_back(centre(sx, sy, n));
        sx = sy = 0.0;
        n = 0;
      }
      sx += p.x;
      sy += p.y;
      ++n;
    }
    if (n > 0) out.poses.push_back(centre(sx, sy, n));
  }

  static geometry_msgs::Pose centre(double sx, double sy, int n) {
    geometry_msgs::Pose pose;
    pose.position.x = sx / n;
    pose.position.y = sy / n;
    pose.orientation.w = 1.0;
    return pose;
  }

  void reportCount(const ros::TimerEvent&) {
    std_msgs::Int32 count;
    count.data = tracked_;
    count_pub_.publish(count);
  }

  ros::Publisher obstacles_pub_;
  ros::Publisher count_pub_;
  ros::Subscriber points_sub_;
  ros::Timer count_timer_;
  double cluster_gap_ = 0.3;
  int tracked_ = 0;
};

}  // namespace obstacle_pipeline

int main(int argc, char** argv) {
  ros::init(argc, argv, "obstacle_tracker");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  obstacle_pipeline::ObstacleTracker tracker(nh, pnh);
  ros::spin();
  return 0;
}
