// Auto-exposure loop: measures the mean brightness of the left image and answers with a new
// exposure time. Its topics live under the namespace of its "camera" NodeHandle, which the
// launch file points at the stereo head.
#include <ros/ros.h>
#include <sensor_msgs/Image.h>
#include <std_msgs/Float32.h>

class AutoExposure {
 public:
  explicit AutoExposure(ros::NodeHandle& camera) {
    image_sub_ = camera.subscribe("left/image_raw", 1, &AutoExposure::onImage, this);
    exposure_pub_ = camera.advertise<std_msgs::Float32>("exposure", 1);
  }

 private:
  void onImage(const sensor_msgs::Image::ConstPtr& image) {
    double sum = 0.0;
    for (unsigned char pixel : image->data) sum += pixel;
    double mean = image->data.empty() ? 128.0 : sum / image->data.size();
    std_msgs::Float32 exposure;
    exposure.data = static_cast<float>(8.0 * 128.0 / (mean + 1.0));
    exposure_pub_.publish(exposure);
  }

  ros::Subscriber image_sub_;
  ros::Publisher exposure_pub_;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "auto_exposure");
  ros::NodeHandle camera("camera");
  AutoExposure loop(camera);
  ros::spin();
  return 0;
}
