// A component: the odometer integrates wheel ticks and publishes the distance travelled. Its
// name comes from the base initializer; launch files load it as fleet::Odometer.
#include <chrono>
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "rclcpp_components/register_node_macro.hpp"
#include "std_msgs/msg/float64.hpp"
#include "std_msgs/msg/int64.hpp"

using namespace std::chrono_literals;
using std::placeholders::_1;

namespace fleet
{

class Odometer : public rclcpp::Node
{
public:
  explicit Odometer(const rclcpp::NodeOptions & options)
  : Node("odometer", options)
  {
    distance_pub_ = create_publisher<std_msgs::msg::Float64>("distance", rclcpp::QoS(10));
    ticks_sub_ = create_subscription<std_msgs::msg::Int64>(
      "wheel_ticks", 20, std::bind(&Odometer::on_ticks, this, _1));
    report_timer_ = create_wall_timer(250ms, std::bind(&Odometer::report, this));
  }

private:
  void on_ticks(const std_msgs::msg::Int64::SharedPtr msg)
  {
    metres_ += static_cast<double>(msg->data) * metres_per_tick_;
  }

  void report()
  {
    std_msgs::msg::Float64 out;
    out.data = metres_;
    distance_pub_->publish(out);
  }

  double metres_{0.0};
  double metres_per_tick_{0.002};
  rclcpp::Publisher<std_msgs::msg::Float64>::SharedPtr distance_pub_;
  rclcpp::Subscription<std_msgs::msg::Int64>::SharedPtr ticks_sub_;
  rclcpp::TimerBase::SharedPtr report_timer_;
};

// Not the component: a helper node in the same file, which the component's extraction ignores.
class OdometerProbe : public rclcpp::Node
{
public:
  OdometerProbe()
  : Node("odometer_probe")
  {
    probe_sub_ = create_subscription<std_msgs::msg::Float64>(
      "distance", 1, [this](std_msgs::msg::Float64::ConstSharedPtr msg) {last_ = msg->data;});
  }

private:
  double last_{0.0};
  rclcpp::Subscription<std_msgs::msg::Float64>::SharedPtr probe_sub_;
};

}  // namespace fleet

RCLCPP_COMPONENTS_REGISTER_NODE(fleet::Odometer)
