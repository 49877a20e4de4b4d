// An obstacle pipeline stage: each scan goes through helper methods and a free function that get
// the publisher as an argument; a relay object keeps a publisher handed to its constructor;
// per-sector publishers live in a vector; the transform to the sensor is broadcast from the
// callback; a second subscriber's callback is a boost::bind with an extra argument.
#include <string>
#include <vector>

#include <boost/bind.hpp>
#include <geometry_msgs/PoseArray.h>
#include <geometry_msgs/TransformStamped.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/Int32.h>
#include <tf2_ros/transform_broadcaster.h>

namespace
{
void publishCount(const ros::Publisher& pub, int count)
{
  std_msgs::Int32 msg;
  msg.data = count;
  pub.publish(msg);
}
}  // namespace

class Relay
{
public:
  explicit Relay(ros::Publisher pub) : pub_(pub) {}
  void forward(const geometry_msgs::PoseArray& poses) { pub_.publish(poses); }

private:
  ros::Publisher pub_;
};

class ObstacleStage
{
public:
  ObstacleStage(ros::NodeHandle& nh, ros::NodeHandle& pnh)
    : relay_(nh.advertise<geometry_msgs::PoseArray>("obstacles_relayed", 1))
  {
    obstacles_pub_ = nh.advertise<geometry_msgs::PoseArray>("obstacles", 1);
    count_pub_ = pnh.advertise<std_msgs::Int32>("count", 1);
    for (const std::string name : {"front", "rear"}) {
      sector_pubs_.push_back(pnh.advertise<std_msgs::Int32>(name, 1));
    }
    scan_sub_ = nh.subscribe("scan", 1, &ObstacleStage::scanCallback, this);
    aux_sub_ = nh.subscribe<sensor_msgs::LaserScan>("aux_scan", 1,
                                                    boost::bind(&ObstacleStage::auxCallback, this, _1, 1));
  }

private:
  void scanCallback(const sensor_msgs::LaserScan::ConstPtr& scan) { process(*scan, 0); }

  void auxCallback(const sensor_msgs::LaserScan::ConstPtr& scan, int sector) { process(*scan, sector); }

  void process(const sensor_msgs::LaserScan& scan, int sector)
  {
    geometry_msgs::PoseArray obstacles;
    obstacles.header = scan.header;
    for (size_t i = 0; i < scan.ranges.size(); ++i) {
      if (scan.ranges[i] < scan.range_max) {
        obstacles.poses.emplace_back();
      }
    }
    report(obstacles, sector);
  }

  void report(const geometry_msgs::PoseArray& obstacles, int sector)
  {
    obstacles_pub_.publish(obstacles);
    relay_.forward(obstacles);
    publishCount(count_pub_, static_cast<int>(obstacles.poses.size()));
    publishCount(sector_pubs_[sector], static_cast<int>(obstacles.poses.size()));
    geometry_msgs::TransformStamped sensor;
    sensor.header = obstacles.header;
    sensor.child_frame_id = "obstacle_sensor";
    sensor.transform.rotation.w = 1.0;
    broadcaster_.sendTransform(sensor);
  }

  Relay relay_;
  ros::Publisher obstacles_pub_;
  ros::Publisher count_pub_;
  std::vector<ros::Publisher> sector_pubs_;
  ros::Subscriber scan_sub_;
  ros::Subscriber aux_sub_;
  tf2_ros::TransformBroadcaster broadcaster_;
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "obstacle_stage");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  ObstacleStage stage(nh, pnh);
  ros::spin();
  return 0;
}
