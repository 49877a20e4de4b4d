// A nodelet exported through a typedef (as pcl_ros exports its filters), whose ports are set up by
// its base classes: nodelet_topic_tools::NodeletLazy's pnh_ (reset to the private handle in a
// header archlog does not otherwise read) and advertise<T>(nh, topic, queue), a tf listener
// member, and a diagnostics updater made with boost::make_shared. Only the exported class and its
// bases are the node: Unrelated's port is not.
#include <boost/make_shared.hpp>
#include <diagnostic_updater/diagnostic_updater.h>
#include <nodelet_topic_tools/nodelet_lazy.h>
#include <pluginlib/class_list_macros.hpp>
#include <ros/ros.h>
#include <sensor_msgs/PointCloud2.h>
#include <tf/transform_listener.h>

namespace clouds
{
class CloudNodelet : public nodelet_topic_tools::NodeletLazy
{
protected:
  void onInit() override
  {
    NodeletLazy::onInit();
    pub_ = advertise<sensor_msgs::PointCloud2>(*pnh_, "output", 1);
    updater_ = boost::make_shared<diagnostic_updater::Updater>();
    onInitPostProcess();
  }

  void subscribe() override
  {
    sub_ = pnh_->subscribe("input", 1, &CloudNodelet::cloudCb, this);
  }

  void unsubscribe() override
  {
    sub_.shutdown();
  }

  void cloudCb(const sensor_msgs::PointCloud2::ConstPtr& cloud)
  {
    pub_.publish(cloud);
  }

  ros::Publisher pub_;
  ros::Subscriber sub_;
  tf::TransformListener tf_listener_;
  boost::shared_ptr<diagnostic_updater::Updater> updater_;
};

class Smooth : public CloudNodelet
{
};

class Unrelated
{
public:
  explicit Unrelated(ros::NodeHandle& nh)
  {
    pub_ = nh.advertise<sensor_msgs::PointCloud2>("elsewhere", 1);
  }

  ros::Publisher pub_;
};
}  // namespace clouds

typedef clouds::Smooth Smooth;
PLUGINLIB_EXPORT_CLASS(Smooth, nodelet::Nodelet)
