// Generates the warehouse floor plan (outer walls and shelf rows) and serves it: latched on
// 'map' / 'map_metadata' and on request through the 'static_map' service.
#include <string>

#include <nav_msgs/GetMap.h>
#include <nav_msgs/MapMetaData.h>
#include <nav_msgs/OccupancyGrid.h>
#include <ros/ros.h>

class MapProvider {
 public:
  MapProvider(ros::NodeHandle& nh, ros::NodeHandle& pnh) : nh_(nh), pnh_(pnh) {
    pnh_.param<std::string>("frame_id", frame_id_, "map");
    pnh_.param("resolution", resolution_, 0.1);
    pnh_.param("width", width_, 120);
    pnh_.param("height", height_, 80);
    build();

    map_pub_ = nh_.advertise<nav_msgs::OccupancyGrid>("map", 1, true);
    metadata_pub_ = nh_.advertise<nav_msgs::MapMetaData>("map_metadata", 1, true);
    map_service_ = nh_.advertiseService("static_map", &MapProvider::onGetMap, this);
    map_pub_.publish(map_);
    metadata_pub_.publish(map_.info);
    pnh_.setParam("cells", static_cast<int>(map_.data.size()));
  }

 private:
  void build() {
    map_.header.frame_id = frame_id_;
    map_.header.stamp = ros::Time::now();
    map_.info.resolution = resolution_;
    map_.info.width = width_;
    map_.info.height = height_;
    map_.info.origin.orientation.w = 1.0;
    map_.data.assign(static_cast<std::size_t>(width_) * height_, 0);
    for (int y = 0; y < height_; ++y) {
      for (int x = 0; x < width_; ++x) {
        const bool wall = x == 0 || y == 0 || x == width_ - 1 || y == height_ - 1;
        const bool shelf = (x % 20 >= 8 && x % 20 < 12) && y > 10 && y < height_ - 10;
        map_.data[y * width_ + x] = (wall || shelf) ? 100 : 0;
      }
    }
  }

  bool onGetMap(nav_msgs::GetMap::Request&, nav_msgs::GetMap::Response& res) {
    res.map = map_;
    return true;
  }

  ros::NodeHandle nh_;
  ros::NodeHandle pnh_;
  ros::Publisher map_pub_, metadata_pub_;
  ros::ServiceServer map_service_;
  nav_msgs::OccupancyGrid map_;
  std::string frame_id_;
  double resolution_ = 0.1;
  int width_ = 120, height_ = 80;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "map_provider");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  MapProvider provider(nh, pnh);
  ros::spin();
  return 0;
}
