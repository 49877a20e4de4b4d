// A waypoint follower whose topic names come from parameters (with defaults), from a prefix
// parameter joined to a literal, and from a sub-node's namespace; parameters also written.
#include <memory>
#include <string>

#include "geometry_msgs/msg/pose_stamped.hpp"
#include "geometry_msgs/msg/twist.hpp"
#include "nav_msgs/msg/path.hpp"
#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"

class Follower : public rclcpp::Node
{
public:
  Follower()
  : Node("follower")
  {
    const std::string path_topic = declare_parameter("path_topic", "plan");
    path_sub_ = create_subscription<nav_msgs::msg::Path>(
      path_topic, 1, [this](nav_msgs::msg::Path::SharedPtr path) {path_ = path;});

    declare_parameter("cmd_topic", rclcpp::ParameterValue(std::string("cmd_vel")));
    get_parameter("cmd_topic", cmd_topic_);
    cmd_pub_ = create_publisher<geometry_msgs::msg::Twist>(cmd_topic_, 10);

    get_parameter_or("goal_topic", goal_topic_, std::string("goal_pose"));
    goal_pub_ = create_publisher<geometry_msgs::msg::PoseStamped>(goal_topic_, 1);

    const auto prefix = declare_parameter<std::string>("robot", "rover");
    status_pub_ = create_publisher<std_msgs::msg::String>(prefix + "/status", 1);

    debug_ = create_sub_node("debug");
    lookahead_pub_ = debug_->create_publisher<geometry_msgs::msg::PoseStamped>("lookahead", 1);

    set_parameter(rclcpp::Parameter("ready", true));
  }

private:
  std::string cmd_topic_;
  std::string goal_topic_;
  nav_msgs::msg::Path::SharedPtr path_;
  rclcpp::Node::SharedPtr debug_;
  rclcpp::Subscription<nav_msgs::msg::Path>::SharedPtr path_sub_;
  rclcpp::Publisher<geometry_msgs::msg::Twist>::SharedPtr cmd_pub_;
  rclcpp::Publisher<geometry_msgs::msg::PoseStamped>::SharedPtr goal_pub_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr status_pub_;
  rclcpp::Publisher<geometry_msgs::msg::PoseStamped>::SharedPtr lookahead_pub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Follower>());
  rclcpp::shutdown();
  return 0;
}
