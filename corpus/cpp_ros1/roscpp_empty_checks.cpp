// A waypoint queue whose state is hidden in container checks: goals are queued by a callback and
// drained by a loop in a worker thread (usleep), a plan is published only while the queue's size
// is not zero, the route name (a string) must be known, and the markers are published for every
// queued goal (a range-for over the queue). Clearing happens on a service.
#include <deque>
#include <string>
#include <thread>
#include <unistd.h>

#include <geometry_msgs/PoseStamped.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <roscpp/Empty.h>
#include <std_msgs/String.h>

class WaypointQueue
{
public:
  explicit WaypointQueue(ros::NodeHandle& nh)
  {
    next_pub_ = nh.advertise<geometry_msgs::PoseStamped>("next_goal", 1);
    plan_pub_ = nh.advertise<nav_msgs::Path>("queued_plan", 1);
    marker_pub_ = nh.advertise<geometry_msgs::PoseStamped>("queued_markers", 10);
    goal_sub_ = nh.subscribe("goal", 10, &WaypointQueue::goalCallback, this);
    route_sub_ = nh.subscribe("route_name", 1, &WaypointQueue::routeCallback, this);
    clear_srv_ = nh.advertiseService("clear", &WaypointQueue::clear, this);
    worker_ = std::thread(&WaypointQueue::drain, this);
  }

  ~WaypointQueue() { worker_.join(); }

private:
  void goalCallback(const geometry_msgs::PoseStamped::ConstPtr& goal)
  {
    queue_.push_back(*goal);
    if (queue_.size() == 0 || route_.empty()) {
      return;
    }
    nav_msgs::Path plan;
    plan.header.frame_id = route_;
    plan.poses.assign(queue_.begin(), queue_.end());
    plan_pub_.publish(plan);
  }

  void routeCallback(const std_msgs::String::ConstPtr& msg) { route_ = msg->data; }

  bool clear(roscpp::Empty::Request&, roscpp::Empty::Response&)
  {
    queue_.clear();
    return true;
  }

  void drain()
  {
    while (ros::ok()) {
      if (queue_.size() > 0) {
        next_pub_.publish(queue_.front());
        queue_.pop_front();
      }
      for (const auto& goal : queue_) {
        marker_pub_.publish(goal);
      }
      usleep(200000);
    }
  }

  ros::Publisher next_pub_;
  ros::Publisher plan_pub_;
  ros::Publisher marker_pub_;
  ros::Subscriber goal_sub_;
  ros::Subscriber route_sub_;
  ros::ServiceServer clear_srv_;
  std::deque<geometry_msgs::PoseStamped> queue_;
  std::string route_;
  std::thread worker_;
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "waypoint_queue");
  ros::NodeHandle nh;
  WaypointQueue queue(nh);
  ros::spin();
  return 0;
}
