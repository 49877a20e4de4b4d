// A lifecycle planner: needs the map (sent once, so it subscribes transient local) and goals.
#include <memory>
#include <string>

#include "geometry_msgs/msg/pose_stamped.hpp"
#include "nav_msgs/msg/occupancy_grid.hpp"
#include "nav_msgs/msg/path.hpp"
#include "rclcpp/rclcpp.hpp"
#include "rclcpp_lifecycle/lifecycle_node.hpp"

using std::placeholders::_1;

class GridPlanner : public rclcpp_lifecycle::LifecycleNode
{
public:
  GridPlanner()
  : rclcpp_lifecycle::LifecycleNode("grid_planner")
  {
    const std::string map_topic = this->declare_parameter("map_topic", std::string("map"));
    map_sub_ = this->create_subscription<nav_msgs::msg::OccupancyGrid>(
      map_topic, rclcpp::QoS(rclcpp::KeepLast(1)).transient_local().reliable(),
      std::bind(&GridPlanner::on_map, this, _1));
    goal_sub_ = this->create_subscription<geometry_msgs::msg::PoseStamped>(
      "goal_pose", 10, [this](geometry_msgs::msg::PoseStamped::SharedPtr goal) {plan_to(*goal);});
    path_pub_ = this->create_publisher<nav_msgs::msg::Path>("plan", 1);
  }

private:
  void on_map(nav_msgs::msg::OccupancyGrid::SharedPtr map)
  {
    map_ = map;
  }

  void plan_to(const geometry_msgs::msg::PoseStamped & goal)
  {
    if (!map_) {
      return;
    }
    nav_msgs::msg::Path path;
    path.header.frame_id = map_->header.frame_id;
    path.poses.push_back(goal);
    path_pub_->publish(path);
  }

  nav_msgs::msg::OccupancyGrid::SharedPtr map_;
  rclcpp::Subscription<nav_msgs::msg::OccupancyGrid>::SharedPtr map_sub_;
  rclcpp::Subscription<geometry_msgs::msg::PoseStamped>::SharedPtr goal_sub_;
  rclcpp_lifecycle::LifecyclePublisher<nav_msgs::msg::Path>::SharedPtr path_pub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<GridPlanner>();
  rclcpp::spin(node->get_node_base_interface());
  rclcpp::shutdown();
  return 0;
}
