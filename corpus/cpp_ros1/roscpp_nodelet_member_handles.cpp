// A nodelet whose handles are members set in onInit, defined outside its class (image_proc's
// resize nodelet): a NodeHandle assigned from getNodeHandle(), a smart pointer reset to a new
// private handle, and an image transport made on it. Ports on them are public or private as set.
#include <image_transport/image_transport.h>
#include <memory>
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>

namespace scaler
{
class ScaleNodelet : public nodelet::Nodelet
{
  ros::NodeHandle nh_;
  std::shared_ptr<ros::NodeHandle> pnh_;
  std::shared_ptr<image_transport::ImageTransport> private_it_;
  image_transport::Publisher pub_image_;
  ros::Publisher pub_info_;
  ros::Subscriber sub_info_;

  void onInit() override;
  void infoCb(const sensor_msgs::CameraInfoConstPtr& info);
};

void ScaleNodelet::onInit()
{
  nh_ = getNodeHandle();
  pnh_.reset(new ros::NodeHandle(getPrivateNodeHandle()));
  private_it_.reset(new image_transport::ImageTransport(*pnh_));
  pub_image_ = private_it_->advertise("image", 1);
  pub_info_ = pnh_->advertise<sensor_msgs::CameraInfo>("camera_info", 1);
  sub_info_ = nh_.subscribe("camera_info", 1, &ScaleNodelet::infoCb, this);
}

void ScaleNodelet::infoCb(const sensor_msgs::CameraInfoConstPtr& info)
{
  pub_info_.publish(info);
}
}  // namespace scaler

PLUGINLIB_EXPORT_CLASS(scaler::ScaleNodelet, nodelet::Nodelet)
