// Simulated planar laser: a wall two metres ahead with a post that drifts across the view.
#include <cmath>
#include <string>

#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>

int main(int argc, char** argv) {
  ros::init(argc, argv, "scan_simulator");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");

  std::string topic;
  pnh.param<std::string>("topic", topic, "scan");
  std::string frame_id;
  pnh.param<std::string>("frame_id", frame_id, "laser");
  double rate;
  ros::param::param("~rate", rate, 10.0);

  ros::Publisher scan_pub = nh.advertise<sensor_msgs::LaserScan>(topic, 5);

  const int beams = 181;
  ros::Rate loop(rate);
  double t = 0.0;
  while (ros::ok()) {
    sensor_msgs::LaserScan scan;
    scan.header.stamp = ros::Time::now();
    scan.header.frame_id = frame_id;
    scan.angle_min = -M_PI / 2.0;
    scan.angle_max = M_PI / 2.0;
    scan.angle_increment = M_PI / (beams - 1);
    scan.range_min = 0.05;
    scan.range_max = 10.0;
    scan.ranges.resize(beams);
    const double post = 0.8 * std::sin(t);
    for (int i = 0; i < beams; ++i) {
      const double a = scan.angle_min + i * scan.angle_increment;
      const double wall = 2.0 / std::max(std::cos(a), 0.2);
      scan.ranges[i] = std::abs(a - post) < 0.05 ? 1.2 : static_cast<float>(std::min(wall, 10.0));
    }
    scan_pub.publish(scan);
    t += 1.0 / rate;
    loop.sleep();
  }
  return 0;
}
