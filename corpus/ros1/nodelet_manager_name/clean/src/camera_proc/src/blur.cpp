#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>
#include <ros/ros.h>
#include <sensor_msgs/Image.h>

namespace camera_proc
{
class Blur : public nodelet::Nodelet
{
  void onInit() override
  {
    ros::NodeHandle& nh = getNodeHandle();
    pub_ = nh.advertise<sensor_msgs::Image>("image_blurred", 1);
    sub_ = nh.subscribe("image_raw", 1, &Blur::imageCb, this);
  }

  void imageCb(const sensor_msgs::Image::ConstPtr& msg)
  {
    pub_.publish(msg);
  }

  ros::Publisher pub_;
  ros::Subscriber sub_;
};
}  // namespace camera_proc

PLUGINLIB_EXPORT_CLASS(camera_proc::Blur, nodelet::Nodelet)
