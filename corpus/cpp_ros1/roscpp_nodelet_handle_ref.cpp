// Handles taken by reference from the nodelet accessors in a class template (so `this->...` is a
// dependent call libclang leaves unresolved, as it does when a nodelet's headers are missing).
#include <nodelet/nodelet.h>
#include <ros/ros.h>
#include <std_msgs/String.h>

namespace mux_demo {

template <class Base>
class MuxNodelet : public Base {
 public:
  void onInit() override {
    ros::NodeHandle &nh = this->getPrivateNodeHandle();
    active_pub_ = nh.advertise<std_msgs::String>("active", 1, true);
    ros::NodeHandle& shared = this->getMTNodeHandle();
    output_pub_ = shared.advertise<std_msgs::String>("output", 1);
  }

 private:
  ros::Publisher active_pub_;
  ros::Publisher output_pub_;
};

template class MuxNodelet<nodelet::Nodelet>;

}  // namespace mux_demo
