// Command buffer: route waypoints are buffered as they arrive and drained one per cycle of a
// 20 Hz loop into the target the steering controller tracks; the buffer depth is always reported.
#include <deque>

#include <geometry_msgs/Point.h>
#include <geometry_msgs/PoseStamped.h>
#include <ros/ros.h>
#include <std_msgs/UInt32.h>

class CommandBuffer {
 public:
  CommandBuffer() : pnh_("~") {
    target_pub_ = nh_.advertise<geometry_msgs::Point>("buffered_target", 1);
    depth_pub_ = pnh_.advertise<std_msgs::UInt32>("depth", 1);
    waypoint_sub_ = nh_.subscribe("route_waypoints", 10, &CommandBuffer::waypointCallback, this);
  }

  void spin() {
    ros::Rate rate(20.0);
    while (ros::ok()) {
      ros::spinOnce();
      std_msgs::UInt32 depth;
      depth.data = static_cast<unsigned>(buffer_.size());
      depth_pub_.publish(depth);
      if (!buffer_.empty()) {
        target_pub_.publish(buffer_.front().pose.position);
        buffer_.pop_front();
      }
      rate.sleep();
    }
  }

 private:
  void waypointCallback(const geometry_msgs::PoseStamped::ConstPtr& msg) { buffer_.push_back(*msg); }

  ros::NodeHandle nh_;
  ros::NodeHandle pnh_;
  ros::Publisher target_pub_;
  ros::Publisher depth_pub_;
  ros::Subscriber waypoint_sub_;
  std::deque<geometry_msgs::PoseStamped> buffer_;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "command_buffer");
  CommandBuffer buffer;
  buffer.spin();
  return 0;
}
