// Synthetic camera: publishes a moving gradient and its calibration through image_transport.
#include <cstdint>
#include <string>

#include <image_transport/image_transport.h>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>

namespace {
sensor_msgs::CameraInfo makeInfo(const std::string& frame_id, int width, int height) {
  sensor_msgs::CameraInfo info;
  info.header.frame_id = frame_id;
  info.width = width;
  info.height = height;
  info.distortion_model = "plumb_bob";
  info.D = {0.0, 0.0, 0.0, 0.0, 0.0};
  const double f = 0.8 * width;
  info.K = {f, 0.0, width / 2.0, 0.0, f, height / 2.0, 0.0, 0.0, 1.0};
  info.R = {1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0};
  info.P = {f, 0.0, width / 2.0, 0.0, 0.0, f, height / 2.0, 0.0, 0.0, 0.0, 1.0, 0.0};
  return info;
}
}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "camera_driver");
  ros::NodeHandle nh;
  double fps;
  ros::param::param("~fps", fps, 15.0);

  ros::NodeHandle pnh("~");
  std::string frame_id;
  pnh.param<std::string>("frame_id", frame_id, "camera_optical_frame");
  int width, height;
  pnh.param("width", width, 80);
  pnh.param("height", height, 60);

  image_transport::ImageTransport it(nh);
  image_transport::CameraPublisher camera_pub = it.advertiseCamera("image_raw", 1);

  sensor_msgs::CameraInfo info = makeInfo(frame_id, width, height);
  ros::Rate loop(fps);
  std::uint8_t phase = 0;
  while (ros::ok()) {
    sensor_msgs::Image image;
    image.header.stamp = ros::Time::now();
    image.header.frame_id = frame_id;
    image.width = width;
    image.height = height;
    image.encoding = "mono8";
    image.step = width;
    image.data.resize(static_cast<std::size_t>(width) * height);
    for (int v = 0; v < height; ++v)
      for (int u = 0; u < width; ++u) image.data[v * width + u] = static_cast<std::uint8_t>(u + v + phase);
    info.header.stamp = image.header.stamp;
    camera_pub.publish(image, info);
    ++phase;
    ros::spinOnce();
    loop.sleep();
  }
  return 0;
}
