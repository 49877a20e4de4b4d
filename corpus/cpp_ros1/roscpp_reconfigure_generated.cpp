// A nodelet whose base class comes from a header missing here (so libclang cannot resolve the
// class's calls): its handle, its dynamic_reconfigure servers (Config generated at build time; one
// in a member template, which libclang leaves unresolved) and its publisher, in the private namespace.
#include <dynamic_reconfigure/server.h>
#include <ros/ros.h>
#include <std_msgs/Float64.h>

#include "throttle_demo/ThrottleConfig.h"
#include "vendor_base/vendor_nodelet.h"

namespace throttle_demo {

class ThrottleNodelet : public vendor_base::VendorNodelet {
 public:
  void onInit();
  template <class Config>
  void serve(ros::NodeHandle& nh) {
    auto* server = new dynamic_reconfigure::Server<Config>(nh);
  }

 private:
  dynamic_reconfigure::Server<throttle_demo::ThrottleConfig>* server_;
  ros::Publisher rate_pub_;
};

void ThrottleNodelet::onInit() {
  ros::NodeHandle& pnh = this->getPrivateNodeHandle();
  server_ = new dynamic_reconfigure::Server<throttle_demo::ThrottleConfig>(pnh);
  rate_pub_ = pnh.advertise<std_msgs::Float64>("rate", 1);
  ros::NodeHandle limits_nh("limits");
  serve<throttle_demo::ThrottleConfig>(limits_nh);
}

}  // namespace throttle_demo
