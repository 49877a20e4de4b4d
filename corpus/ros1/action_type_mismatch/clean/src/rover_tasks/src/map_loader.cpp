// Action server that "loads" the docking-area map on request (nav_msgs/GetMap action) and
// republishes the loaded map, latched, for the rest of the system.
#include <string>

#include <actionlib/server/simple_action_server.h>
#include <boost/bind/bind.hpp>
#include <nav_msgs/GetMapAction.h>
#include <nav_msgs/OccupancyGrid.h>
#include <ros/ros.h>

class MapLoader {
 public:
  MapLoader(ros::NodeHandle& nh, const std::string& action_name)
      : nh_(nh),
        pnh_("~"),
        server_(nh_, action_name, boost::bind(&MapLoader::execute, this, boost::placeholders::_1), false) {
    pnh_.param("size", size_, 40);
    pnh_.param<std::string>("frame_id", frame_id_, "map");
    map_pub_ = nh_.advertise<nav_msgs::OccupancyGrid>("dock_map", 1, true);
    server_.start();
  }

 private:
  void execute(const nav_msgs::GetMapGoalConstPtr&) {
    nav_msgs::GetMapFeedback feedback;
    server_.publishFeedback(feedback);
    nav_msgs::GetMapResult result;
    result.map.header.frame_id = frame_id_;
    result.map.header.stamp = ros::Time::now();
    result.map.info.resolution = 0.05;
    result.map.info.width = size_;
    result.map.info.height = size_;
    result.map.info.origin.orientation.w = 1.0;
    result.map.data.assign(static_cast<std::size_t>(size_) * size_, 0);
    for (int i = 0; i < size_; ++i) result.map.data[i] = 100;  // the docking wall
    map_pub_.publish(result.map);
    server_.setSucceeded(result);
  }

  ros::NodeHandle nh_, pnh_;
  actionlib::SimpleActionServer<nav_msgs::GetMapAction> server_;
  ros::Publisher map_pub_;
  int size_ = 40;
  std::string frame_id_;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "map_loader");
  ros::NodeHandle nh;
  MapLoader loader(nh, "load_dock_map");
  ros::spin();
  return 0;
}
