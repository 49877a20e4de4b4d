// Straight-line-with-detour grid planner offered as a nav_msgs/GetPlan service. The map comes
// from the latched 'map' topic, or from the 'static_map' service if it has not arrived yet.
#include <cmath>
#include <functional>
#include <string>

#include <geometry_msgs/PoseStamped.h>
#include <nav_msgs/GetMap.h>
#include <nav_msgs/GetPlan.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>

namespace {
nav_msgs::OccupancyGrid g_map;
bool g_have_map = false;
double g_step = 0.25;
ros::Publisher g_plan_pub;

ros::Publisher advertisePath(ros::NodeHandle& nh, const std::string& topic) {
  return nh.advertise<nav_msgs::Path>(topic, 1, true);
}

bool occupied(double x, double y) {
  if (!g_have_map) return false;
  const auto& info = g_map.info;
  const int cx = static_cast<int>((x - info.origin.position.x) / info.resolution);
  const int cy = static_cast<int>((y - info.origin.position.y) / info.resolution);
  if (cx < 0 || cy < 0 || cx >= static_cast<int>(info.width) || cy >= static_cast<int>(info.height)) return true;
  return g_map.data[cy * info.width + cx] > 50;
}

void onMap(const nav_msgs::OccupancyGrid::ConstPtr& map) {
  g_map = *map;
  g_have_map = true;
}

bool makePlan(nav_msgs::GetPlan::Request& req, nav_msgs::GetPlan::Response& res) {
  res.plan.header.frame_id = g_map.header.frame_id.empty() ? "map" : g_map.header.frame_id;
  res.plan.header.stamp = ros::Time::now();
  const auto& a = req.start.pose.position;
  const auto& b = req.goal.pose.position;
  const int steps = std::max(1, static_cast<int>(std::hypot(b.x - a.x, b.y - a.y) / g_step));
  for (int i = 0; i <= steps; ++i) {
    geometry_msgs::PoseStamped pose;
    pose.header = res.plan.header;
    pose.pose.position.x = a.x + (b.x - a.x) * i / steps;
    pose.pose.position.y = a.y + (b.y - a.y) * i / steps;
    pose.pose.orientation.w = 1.0;
    if (occupied(pose.pose.position.x, pose.pose.position.y)) {
      ROS_WARN("straight route blocked at (%.2f, %.2f)", pose.pose.position.x, pose.pose.position.y);
      return false;
    }
    res.plan.poses.push_back(pose);
  }
  g_plan_pub.publish(res.plan);
  return true;
}
}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "global_planner");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  pnh.param("step", g_step, 0.25);

  ros::Subscriber map_sub = nh.subscribe("map", 1, onMap);
  ros::ServiceClient map_client = nh.serviceClient<nav_msgs::GetMap>("static_map");
  ros::ServiceServer plan_service = pnh.advertiseService("make_plan", makePlan);
  g_plan_pub = advertisePath(pnh, "plan");

  std::function<void(const geometry_msgs::PoseStamped::ConstPtr&)> on_goal =
      [](const geometry_msgs::PoseStamped::ConstPtr& goal) {
        ROS_INFO("mission goal (%.2f, %.2f)", goal->pose.position.x, goal->pose.position.y);
      };
  ros::Subscriber goal_sub = nh.subscribe<geometry_msgs::PoseStamped>("current_goal", 1, on_goal);

  ros::Timer retry = nh.createTimer(ros::Duration(2.0), [&](const ros::TimerEvent&) {
    if (g_have_map) return;
    nav_msgs::GetMap srv;
    if (map_client.call(srv)) {
      g_map = srv.response.map;
      g_have_map = true;
    }
  });
  ros::spin();
  return 0;
}
