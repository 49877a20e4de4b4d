// Pairs rectified camera frames with laser scans of the same instant and reports the obstacles
// that both sensors see, as bearings projected into the image.
#include <cmath>
#include <string>

#include <boost/bind/bind.hpp>
#include <boost/function.hpp>
#include <geometry_msgs/PoseArray.h>
#include <message_filters/subscriber.h>
#include <message_filters/time_synchronizer.h>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/LaserScan.h>

class LidarCameraFusion {
 public:
  LidarCameraFusion(ros::NodeHandle& nh, const std::string& image_topic)
      : image_sub_(nh, image_topic, 5), scan_sub_(nh, "front_scan", 5), sync_(image_sub_, scan_sub_, 10) {
    using namespace boost::placeholders;
    sync_.registerCallback(boost::bind(&LidarCameraFusion::onPair, this, _1, _2));

    boost::function<void(const sensor_msgs::CameraInfo::ConstPtr&)> on_info =
        [this](const sensor_msgs::CameraInfo::ConstPtr& info) { fx_ = info->K[0]; };
    info_sub_ = nh.subscribe("camera/camera_info", 1, on_info);
    obstacles_pub_ = nh.advertise<geometry_msgs::PoseArray>("obstacles", 5);
  }

 private:
  void onPair(const sensor_msgs::ImageConstPtr& image, const sensor_msgs::LaserScanConstPtr& scan) {
    geometry_msgs::PoseArray obstacles;
    obstacles.header = scan->header;
    for (std::size_t i = 0; i < scan->ranges.size(); ++i) {
      const float r = scan->ranges[i];
      if (!std::isfinite(r) || r > 1.5f) continue;
      const double a = scan->angle_min + i * scan->angle_increment;
      const double column = image->width / 2.0 - fx_ * std::tan(a);
      if (column < 0.0 || column >= image->width) continue;
      geometry_msgs::Pose pose;
      pose.position.x = r * std::cos(a);
      pose.position.y = r * std::sin(a);
      pose.orientation.w = 1.0;
      obstacles.poses.push_back(pose);
    }
    obstacles_pub_.publish(obstacles);
  }

  message_filters::Subscriber<sensor_msgs::Image> image_sub_;
  message_filters::Subscriber<sensor_msgs::LaserScan> scan_sub_;
  message_filters::TimeSynchronizer<sensor_msgs::Image, sensor_msgs::LaserScan> sync_;
  ros::Subscriber info_sub_;
  ros::Publisher obstacles_pub_;
  double fx_ = 64.0;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "lidar_camera_fusion");
  ros::NodeHandle nh;
  LidarCameraFusion fusion(nh, "camera/image_rect_color");
  ros::spin();
  return 0;
}
