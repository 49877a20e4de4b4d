// Ultrasonic ranger driver stub; one instance per physical sensor.
#include <string>

#include <ros/ros.h>
#include <sensor_msgs/Range.h>

class SonarDriver {
 public:
  explicit SonarDriver(ros::NodeHandle& nh) : pnh_("~") {
    pnh_.param<std::string>("frame_id", msg_.header.frame_id, "sonar");
    pnh_.param("distance", distance_, 1.2);
    msg_.radiation_type = sensor_msgs::Range::ULTRASOUND;
    msg_.field_of_view = 0.5f;
    msg_.min_range = 0.02f;
    msg_.max_range = 4.0f;
    range_pub_ = nh.advertise<sensor_msgs::Range>("range", 5);
    timer_ = nh.createTimer(ros::Duration(0.1), &SonarDriver::poll, this);
  }

 private:
  void poll(const ros::TimerEvent& ev) {
    msg_.header.stamp = ev.current_real;
    msg_.range = static_cast<float>(distance_);
    range_pub_.publish(msg_);
  }

  ros::NodeHandle pnh_;
  ros::Publisher range_pub_;
  ros::Timer timer_;
  sensor_msgs::Range msg_;
  double distance_ = 1.2;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "sonar_driver");
  ros::NodeHandle nh;
  SonarDriver driver(nh);
  ros::spin();
  return 0;
}
