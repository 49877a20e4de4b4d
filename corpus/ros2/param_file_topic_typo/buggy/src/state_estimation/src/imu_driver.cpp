// Publishes IMU samples at 100 Hz.
#include <chrono>
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/imu.hpp"

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = rclcpp::Node::make_shared("imu_driver");
  auto frame = node->declare_parameter<std::string>("frame_id", "imu_link");
  auto pub = node->create_publisher<sensor_msgs::msg::Imu>("imu/data", 10);
  auto timer = node->create_wall_timer(
    std::chrono::milliseconds(10), [node, pub, frame]() {
      sensor_msgs::msg::Imu sample;
      sample.header.frame_id = frame;
      sample.header.stamp = node->now();
      pub->publish(sample);
    });
  rclcpp::spin(node);
  rclcpp::shutdown();
  return 0;
}
