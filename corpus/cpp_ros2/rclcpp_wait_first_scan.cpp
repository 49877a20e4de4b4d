// A scan gate component: its wall timer publishes the closest obstacle only after a first scan
// (a shared pointer the subscription sets) and while a range is known (std::optional); a lambda
// timer made with rclcpp::create_timer publishes a heartbeat; the node announces itself from its
// constructor; a parameter callback publishes when the limit changes.
#include <chrono>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "rclcpp/rclcpp.hpp"
#include "rclcpp_components/register_node_macro.hpp"
#include "sensor_msgs/msg/laser_scan.hpp"
#include "std_msgs/msg/empty.hpp"
#include "std_msgs/msg/float32.hpp"
#include "std_msgs/msg/string.hpp"

using namespace std::chrono_literals;

namespace gate
{

class ScanGate : public rclcpp::Node
{
public:
  explicit ScanGate(const rclcpp::NodeOptions & options)
  : Node("scan_gate", options)
  {
    closest_pub_ = create_publisher<std_msgs::msg::Float32>("closest", 10);
    beat_pub_ = create_publisher<std_msgs::msg::Empty>("~/heartbeat", 1);
    status_pub_ = create_publisher<std_msgs::msg::String>("~/status", rclcpp::QoS(1).transient_local());
    scan_sub_ = create_subscription<sensor_msgs::msg::LaserScan>(
      "scan", rclcpp::SensorDataQoS(),
      [this](sensor_msgs::msg::LaserScan::SharedPtr scan) {
        last_scan_ = scan;
        min_range_.reset();
        for (float r : scan->ranges) {
          if (!min_range_ || r < *min_range_) {
            min_range_ = r;
          }
        }
      });
    gate_timer_ = create_wall_timer(100ms, std::bind(&ScanGate::on_gate, this));
    beat_timer_ = rclcpp::create_timer(
      this, get_clock(), rclcpp::Duration::from_seconds(1.0), [this]() {beat_pub_->publish(std_msgs::msg::Empty());});
    limit_callback_ = add_on_set_parameters_callback(
      [this](const std::vector<rclcpp::Parameter> &) {
        status_pub_->publish(std_msgs::msg::String());
        return rcl_interfaces::msg::SetParametersResult();
      });
    std_msgs::msg::String status;
    status.data = "waiting for scan";
    status_pub_->publish(status);
  }

private:
  void on_gate()
  {
    if (!last_scan_ || !min_range_.has_value()) {
      return;
    }
    std_msgs::msg::Float32 closest;
    closest.data = *min_range_;
    closest_pub_->publish(closest);
  }

  rclcpp::Publisher<std_msgs::msg::Float32>::SharedPtr closest_pub_;
  rclcpp::Publisher<std_msgs::msg::Empty>::SharedPtr beat_pub_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr status_pub_;
  rclcpp::Subscription<sensor_msgs::msg::LaserScan>::SharedPtr scan_sub_;
  rclcpp::TimerBase::SharedPtr gate_timer_;
  rclcpp::TimerBase::SharedPtr beat_timer_;
  rclcpp::node_interfaces::OnSetParametersCallbackHandle::SharedPtr limit_callback_;
  sensor_msgs::msg::LaserScan::SharedPtr last_scan_;
  std::optional<float> min_range_;
};

}  // namespace gate

RCLCPP_COMPONENTS_REGISTER_NODE(gate::ScanGate)
