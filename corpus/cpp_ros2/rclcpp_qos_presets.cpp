// A perception front end: rclcpp's preset QoS classes, rmw profiles (whole, through
// QoSInitialization::from_rmw, and a local rmw_qos_profile_t changed field by field), an
// aggregate-initialised profile, and depths from constants and constexpr variables.
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "rmw/qos_profiles.h"
#include "rosgraph_msgs/msg/clock.hpp"
#include "sensor_msgs/msg/imu.hpp"
#include "sensor_msgs/msg/point_cloud2.hpp"
#include "std_msgs/msg/string.hpp"

static constexpr size_t kCloudDepth = 2;

class FrontEnd : public rclcpp::Node
{
public:
  FrontEnd()
  : Node("front_end")
  {
    auto noop_cloud = [](sensor_msgs::msg::PointCloud2::ConstSharedPtr) {};
    auto noop_imu = [](sensor_msgs::msg::Imu::ConstSharedPtr) {};
    create_subscription<sensor_msgs::msg::PointCloud2>("points", rclcpp::SensorDataQoS(), noop_cloud);
    create_subscription<sensor_msgs::msg::PointCloud2>(
      "points_latest", rclcpp::SensorDataQoS(rclcpp::KeepLast(1)), noop_cloud);
    create_subscription<sensor_msgs::msg::PointCloud2>("points_deep", kCloudDepth, noop_cloud);
    create_subscription<sensor_msgs::msg::Imu>("imu", rclcpp::SystemDefaultsQoS(), noop_imu);
    create_subscription<rosgraph_msgs::msg::Clock>(
      "/clock", rclcpp::ClockQoS(), [](rosgraph_msgs::msg::Clock::ConstSharedPtr) {});
    params_pub_ = create_publisher<std_msgs::msg::String>("param_dump", rclcpp::ParametersQoS());
    log_pub_ = create_publisher<std_msgs::msg::String>("log", rclcpp::RosoutQoS());
    events_pub_ = create_publisher<std_msgs::msg::String>("events", rclcpp::ServicesQoS().best_effort());

    const auto imu_profile = rmw_qos_profile_sensor_data;
    create_subscription<sensor_msgs::msg::Imu>(
      "imu_raw", rclcpp::QoS(rclcpp::QoSInitialization::from_rmw(imu_profile), imu_profile), noop_imu);

    rmw_qos_profile_t custom = rmw_qos_profile_default;
    custom.depth = 4;
    custom.reliability = RMW_QOS_POLICY_RELIABILITY_BEST_EFFORT;
    custom.durability = RMW_QOS_POLICY_DURABILITY_TRANSIENT_LOCAL;
    create_subscription<sensor_msgs::msg::Imu>(
      "imu_filtered", rclcpp::QoS(rclcpp::QoSInitialization::from_rmw(custom), custom), noop_imu);

    rmw_qos_profile_t spelled_out = {
      RMW_QOS_POLICY_HISTORY_KEEP_LAST, 7, RMW_QOS_POLICY_RELIABILITY_RELIABLE,
      RMW_QOS_POLICY_DURABILITY_VOLATILE, {0, 200000000}, RMW_QOS_LIFESPAN_DEFAULT,
      RMW_QOS_POLICY_LIVELINESS_AUTOMATIC, RMW_QOS_LIVELINESS_LEASE_DURATION_DEFAULT, false};
    create_subscription<sensor_msgs::msg::Imu>(
      "imu_checked", rclcpp::QoS(rclcpp::KeepLast(7), spelled_out), noop_imu);
  }

private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr params_pub_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr log_pub_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr events_pub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<FrontEnd>());
  rclcpp::shutdown();
  return 0;
}
