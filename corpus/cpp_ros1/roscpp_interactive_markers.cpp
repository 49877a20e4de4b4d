// An interactive marker server (a class member built in the constructor's initialiser list, and a
// local one whose namespace is a variable): each advertises NS/update and NS/update_full and
// subscribes NS/feedback through a handle in the node's namespace. (interactive_markers is not
// installed with the test machine's ROS packages: its constructor is declared here as its header does.)
#include <ros/ros.h>

#include <string>

namespace interactive_markers {
class InteractiveMarkerServer {
 public:
  InteractiveMarkerServer(const std::string& topic_ns, const std::string& server_id = "", bool spin_thread = false);
};
}  // namespace interactive_markers

class TeleopMarkers {
 public:
  TeleopMarkers() : server_("teleop_markers") {}

 private:
  interactive_markers::InteractiveMarkerServer server_;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "marker_demo");
  TeleopMarkers markers;
  const std::string ns = "goal_markers";
  interactive_markers::InteractiveMarkerServer goals(ns, "goals", true);
  ros::spin();
  return 0;
}
