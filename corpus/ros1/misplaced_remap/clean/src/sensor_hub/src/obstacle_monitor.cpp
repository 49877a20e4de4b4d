// Raises a proximity alert while the sonar reports an obstacle closer than the stop distance.
#include <string>

#include <ros/ros.h>
#include <sensor_msgs/Range.h>
#include <std_msgs/Bool.h>

class ObstacleMonitor {
 public:
  ObstacleMonitor(ros::NodeHandle& nh, ros::NodeHandle& pnh, const std::string& range_topic) {
    pnh.param("stop_distance", stop_distance_, 0.5);
    std::string alert_topic;
    pnh.param<std::string>("alert_topic", alert_topic, "proximity_alert");
    range_sub_ = nh.subscribe(range_topic, 5, &ObstacleMonitor::onRange, this);
    alert_pub_ = nh.advertise<std_msgs::Bool>(alert_topic, 1, true);
    pnh.setParam("active", true);
  }

 private:
  void onRange(const sensor_msgs::Range::ConstPtr& range) {
    std_msgs::Bool alert;
    alert.data = range->range >= range->min_range && range->range < stop_distance_;
    if (alert.data != last_) alert_pub_.publish(alert);
    last_ = alert.data;
  }

  ros::Subscriber range_sub_;
  ros::Publisher alert_pub_;
  double stop_distance_ = 0.5;
  bool last_ = true;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "obstacle_monitor");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  ObstacleMonitor monitor(nh, pnh, "range");
  ros::spin();
  return 0;
}
