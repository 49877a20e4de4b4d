// Synchronised inputs (stereo_image_proc, depth_image_proc): message_filters subscribers and
// image_transport subscriber filters, constructed with their topic or default-constructed and
// subscribed later, feeding a synchronizer. Each is a subscriber of its message type: the
// template argument, or sensor_msgs/Image for an image filter (on the transport's handle).
#include <image_transport/image_transport.h>
#include <image_transport/subscriber_filter.h>
#include <memory>
#include <message_filters/subscriber.h>
#include <message_filters/sync_policies/approximate_time.h>
#include <message_filters/synchronizer.h>
#include <message_filters/time_synchronizer.h>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <stereo_msgs/DisparityImage.h>

using sensor_msgs::CameraInfo;
using sensor_msgs::Image;
namespace sync_policies = message_filters::sync_policies;

class StereoInputs
{
  ros::NodeHandle nh_;
  ros::NodeHandle pnh_{"~"};
  std::shared_ptr<image_transport::ImageTransport> it_;
  image_transport::SubscriberFilter sub_l_image_, sub_r_image_;
  message_filters::Subscriber<CameraInfo> sub_l_info_;
  std::shared_ptr<message_filters::Subscriber<stereo_msgs::DisparityImage>> sub_disparity_;
  typedef sync_policies::ApproximateTime<Image, CameraInfo, Image> Policy;
  std::shared_ptr<message_filters::Synchronizer<Policy>> sync_;

public:
  StereoInputs()
  {
    it_.reset(new image_transport::ImageTransport(nh_));
    image_transport::TransportHints hints("raw", ros::TransportHints(), pnh_);
    sub_l_image_.subscribe(*it_, "left/image_rect", 1, hints);
    sub_l_info_.subscribe(nh_, "left/camera_info", 1);
    sub_r_image_.subscribe(*it_, "right/image_rect", 1, hints);
    sub_disparity_.reset(new message_filters::Subscriber<stereo_msgs::DisparityImage>(pnh_, "disparity", 2));
    sync_.reset(new message_filters::Synchronizer<Policy>(Policy(5), sub_l_image_, sub_l_info_, sub_r_image_));
    sync_->registerCallback(&StereoInputs::imageCb, this);
  }

  void imageCb(const sensor_msgs::ImageConstPtr& l, const sensor_msgs::CameraInfoConstPtr& info,
               const sensor_msgs::ImageConstPtr& r)
  {
  }
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "stereo_inputs");
  ros::NodeHandle nh;
  image_transport::ImageTransport it(nh);
  image_transport::SubscriberFilter depth(it, "depth/image", 1);
  message_filters::Subscriber<CameraInfo> depth_info(nh, "depth/camera_info", 1);
  message_filters::TimeSynchronizer<Image, CameraInfo> sync(depth, depth_info, 10);
  StereoInputs inputs;
  ros::spin();
}
