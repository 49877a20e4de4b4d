// Ports made only when a parameter says so: the member a parameter is read into (without a
// default: the member's initial value is the default) guards which subscriber is made; a
// standalone executable that loads a nodelet into its own process (nodelet::Loader) with a
// remapping, once per call site of the helper that loads it.
#include <nodelet/loader.h>
#include <ros/ros.h>
#include <sensor_msgs/PointCloud2.h>
#include <std_msgs/Empty.h>

class Cropper
{
public:
  Cropper() : use_indices_(false), verbose_(true)
  {
    ros::NodeHandle pnh("~");
    pnh.getParam("use_indices", use_indices_);
    pnh.getParam("verbose", verbose_);
    if (use_indices_)
      indices_sub_ = pnh.subscribe("indices", 1, &Cropper::cloudCb, this);
    else
      input_sub_ = pnh.subscribe("input", 1, &Cropper::cloudCb, this);
    if (!verbose_)
    {
      quiet_pub_ = pnh.advertise<std_msgs::Empty>("quiet", 1);
    }
  }

  void cloudCb(const sensor_msgs::PointCloud2::ConstPtr& cloud) {}

private:
  bool use_indices_;
  bool verbose_;
  ros::Subscriber indices_sub_, input_sub_;
  ros::Publisher quiet_pub_;
};

void loadSide(nodelet::Loader& manager, const std::string& side)
{
  nodelet::M_string remappings;
  nodelet::V_string my_argv;
  remappings["image"] = ros::names::resolve(side + "/image_raw");
  manager.load(ros::this_node::getName() + "_rectify_" + side, "image_proc/rectify", remappings, my_argv);
}

int main(int argc, char** argv)
{
  ros::init(argc, argv, "cropper");
  Cropper cropper;
  nodelet::Loader manager(false);
  loadSide(manager, "left");
  loadSide(manager, "right");
  ros::spin();
}
