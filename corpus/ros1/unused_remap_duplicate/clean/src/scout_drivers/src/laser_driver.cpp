// Laser scanner driver stub: publishes a synthetic 270 degree scan.
#include <algorithm>
#include <cmath>
#include <string>

#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>

int main(int argc, char** argv) {
  ros::init(argc, argv, "laser_driver");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");

  std::string frame_id;
  pnh.param<std::string>("frame_id", frame_id, "laser");
  int beams = pnh.param("beams", 541);
  double hz = pnh.param("frequency", 15.0);

  ros::Publisher scan_pub = nh.advertise<sensor_msgs::LaserScan>("scan", 10);

  sensor_msgs::LaserScan scan;
  scan.header.frame_id = frame_id;
  scan.angle_min = -0.75 * M_PI;
  scan.angle_max = 0.75 * M_PI;
  scan.angle_increment = (scan.angle_max - scan.angle_min) / (beams - 1);
  scan.range_min = 0.06;
  scan.range_max = 20.0;
  scan.scan_time = 1.0 / hz;
  scan.ranges.resize(beams);

  ros::Rate rate(hz);
  while (ros::ok()) {
    scan.header.stamp = ros::Time::now();
    for (int i = 0; i < beams; ++i) {
      const double a = scan.angle_min + i * scan.angle_increment;
      scan.ranges[i] = static_cast<float>(2.0 / std::max(0.1, std::fabs(std::cos(a))));
    }
    scan_pub.publish(scan);
    ros::spinOnce();
    rate.sleep();
  }
  return 0;
}
