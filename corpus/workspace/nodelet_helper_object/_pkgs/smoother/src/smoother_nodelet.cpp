#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.h>
#include "smoother/smoother.hpp"

namespace smoother {

bool Smoother::init(ros::NodeHandle& nh) {
  server_ = new dynamic_reconfigure::Server<smoother::paramsConfig>(nh);
  raw_sub_ = nh.subscribe("raw_cmd_vel", 1, &Smoother::velocityCB, this);
  smooth_pub_ = nh.advertise<geometry_msgs::Twist>("smooth_cmd_vel", 1);
  return true;
}

void Smoother::velocityCB(const geometry_msgs::Twist::ConstPtr& msg) { smooth_pub_.publish(msg); }

class SmootherNodelet : public nodelet::Nodelet {
 public:
  void onInit() override {
    ros::NodeHandle ph = getPrivateNodeHandle();
    smoother_.reset(new Smoother());
    smoother_->init(ph);
  }

 private:
  boost::shared_ptr<Smoother> smoother_;
};

}  // namespace smoother

PLUGINLIB_EXPORT_CLASS(smoother::SmootherNodelet, nodelet::Nodelet)
