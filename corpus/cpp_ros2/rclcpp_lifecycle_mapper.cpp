// A lifecycle node: entities are created in on_configure, the map is latched (transient local),
// a LifecyclePublisher, timers created with create_timer, typed parameter declarations.
#include <chrono>
#include <memory>
#include <string>

#include "nav_msgs/msg/occupancy_grid.hpp"
#include "rclcpp/rclcpp.hpp"
#include "rclcpp_lifecycle/lifecycle_node.hpp"
#include "sensor_msgs/msg/laser_scan.hpp"

using CallbackReturn = rclcpp_lifecycle::node_interfaces::LifecycleNodeInterface::CallbackReturn;

class Mapper : public rclcpp_lifecycle::LifecycleNode
{
public:
  explicit Mapper(const rclcpp::NodeOptions & options = rclcpp::NodeOptions())
  : rclcpp_lifecycle::LifecycleNode("mapper", "mapping", options)
  {
    declare_parameter<double>("resolution", 0.05);
    declare_parameter<std::string>("scan_topic", "scan");
  }

  CallbackReturn on_configure(const rclcpp_lifecycle::State &) override
  {
    const std::string scan_topic = get_parameter("scan_topic").as_string();
    map_pub_ = create_publisher<nav_msgs::msg::OccupancyGrid>(
      "map", rclcpp::QoS(rclcpp::KeepLast(1)).transient_local().reliable());
    scan_sub_ = create_subscription<sensor_msgs::msg::LaserScan>(
      scan_topic, rclcpp::SensorDataQoS(),
      [this](sensor_msgs::msg::LaserScan::ConstSharedPtr scan) {last_range_ = scan->range_max;});
    update_timer_ = create_timer(std::chrono::seconds(2), [this]() {publish_map();});
    return CallbackReturn::SUCCESS;
  }

  CallbackReturn on_activate(const rclcpp_lifecycle::State &) override
  {
    map_pub_->on_activate();
    return CallbackReturn::SUCCESS;
  }

private:
  void publish_map()
  {
    nav_msgs::msg::OccupancyGrid grid;
    grid.info.resolution = static_cast<float>(get_parameter("resolution").as_double());
    map_pub_->publish(grid);
  }

  float last_range_{0.0f};
  rclcpp_lifecycle::LifecyclePublisher<nav_msgs::msg::OccupancyGrid>::SharedPtr map_pub_;
  rclcpp::Subscription<sensor_msgs::msg::LaserScan>::SharedPtr scan_sub_;
  rclcpp::TimerBase::SharedPtr update_timer_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto mapper = std::make_shared<Mapper>();
  rclcpp::spin(mapper->get_node_base_interface());
  rclcpp::shutdown();
  return 0;
}
