// Publishes a synthetic scan at 10 Hz. Scans are sensor data: best effort, shallow queue.
#include <chrono>
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/laser_scan.hpp"

using namespace std::chrono_literals;

class LidarNode : public rclcpp::Node
{
public:
  LidarNode()
  : Node("lidar")
  {
    frame_id_ = this->declare_parameter("frame_id", "laser");
    scan_pub_ = this->create_publisher<sensor_msgs::msg::LaserScan>("scan", rclcpp::SensorDataQoS());
    timer_ = this->create_wall_timer(100ms, std::bind(&LidarNode::on_timer, this));
  }

private:
  void on_timer()
  {
    sensor_msgs::msg::LaserScan scan;
    scan.header.frame_id = frame_id_;
    scan.header.stamp = now();
    scan_pub_->publish(scan);
  }

  std::string frame_id_;
  rclcpp::Publisher<sensor_msgs::msg::LaserScan>::SharedPtr scan_pub_;
  rclcpp::TimerBase::SharedPtr timer_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<LidarNode>());
  rclcpp::shutdown();
  return 0;
}
