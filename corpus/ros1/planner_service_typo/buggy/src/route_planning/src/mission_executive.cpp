// Cycles through the pick stations listed on the parameter server, asking the planner for a
// route to each one and announcing the goal it is driving to.
#include <string>
#include <vector>

#include <geometry_msgs/PoseStamped.h>
#include <nav_msgs/GetMap.h>
#include <nav_msgs/GetPlan.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>

class MissionExecutive {
 public:
  MissionExecutive(ros::NodeHandle& nh, const std::string& planner_service) : nh_(nh), pnh_("~") {
    pnh_.param("stations", stations_, std::vector<double>{1.0, 1.0, 5.0, 1.0, 5.0, 6.0});
    pnh_.param<std::string>("frame_id", frame_id_, "map");
    plan_client_ = nh_.serviceClient<nav_msgs::GetPlan>(planner_service);
    path_sub_ = nh_.subscribe("global_planner/plan", 1, &MissionExecutive::onPath, this);
    goal_pub_ = nh_.advertise<geometry_msgs::PoseStamped>("current_goal", 1, true);
    timer_ = nh_.createTimer(ros::Duration(1.0), &MissionExecutive::onTick, this);
  }

 private:
  void onPath(const nav_msgs::Path::ConstPtr& path) { last_path_length_ = path->poses.size(); }

  void onTick(const ros::TimerEvent&) {
    if (!map_checked_) {
      nav_msgs::GetMap map;
      map_checked_ = ros::service::call("static_map", map);
      if (!map_checked_) return;
    }
    if (stations_.size() < 2) return;
    const std::size_t count = stations_.size() / 2;
    geometry_msgs::PoseStamped start = pose(current_ % count), goal = pose((current_ + 1) % count);
    nav_msgs::GetPlan plan;
    plan.request.start = start;
    plan.request.goal = goal;
    plan.request.tolerance = 0.2;
    if (plan_client_.call(plan)) {
      goal_pub_.publish(goal);
      current_ = (current_ + 1) % count;
    } else {
      ROS_WARN_THROTTLE(10.0, "no route to station %zu", (current_ + 1) % count);
    }
  }

  geometry_msgs::PoseStamped pose(std::size_t station) const {
    geometry_msgs::PoseStamped p;
    p.header.frame_id = frame_id_;
    p.header.stamp = ros::Time::now();
    p.pose.position.x = stations_[2 * station];
    p.pose.position.y = stations_[2 * station + 1];
    p.pose.orientation.w = 1.0;
    return p;
  }

  ros::NodeHandle nh_, pnh_;
  ros::ServiceClient plan_client_;
  ros::Subscriber path_sub_;
  ros::Publisher goal_pub_;
  ros::Timer timer_;
  std::vector<double> stations_;
  std::string frame_id_;
  std::size_t current_ = 0, last_path_length_ = 0;
  bool map_checked_ = false;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "mission_executive");
  ros::NodeHandle nh;
  MissionExecutive executive(nh, "planner/make_plan");
  ros::spin();
  return 0;
}
