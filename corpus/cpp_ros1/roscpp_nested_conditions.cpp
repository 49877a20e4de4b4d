// Ports under nested branches carry every enclosing condition: in the else of `if (use_indices_)`
// inside `if (use_indices_ || use_surface_)`, use_indices_ is false and so use_surface_ is true;
// `a && b` needs both, the else of `a || b` needs neither; a test of something other than a
// parameter's variable (a call) adds no condition.
#include <ros/ros.h>
#include <sensor_msgs/PointCloud2.h>
#include <std_msgs/Empty.h>

class Feature
{
public:
  Feature() : use_indices_(false), use_surface_(false), approximate_(true), debug_(false)
  {
    ros::NodeHandle pnh("~");
    pnh.getParam("use_indices", use_indices_);
    pnh.getParam("use_surface", use_surface_);
    pnh.getParam("approximate_sync", approximate_);
    pnh.getParam("debug", debug_);
    if (use_indices_ || use_surface_)
    {
      if (use_indices_)
      {
        indices_sub_ = pnh.subscribe("indices", 1, &Feature::cloudCb, this);
        if (use_surface_)
          surface_sub_ = pnh.subscribe("surface", 1, &Feature::cloudCb, this);
      }
      else
      {
        surface_only_sub_ = pnh.subscribe("surface", 1, &Feature::cloudCb, this);
      }
    }
    else
      input_sub_ = pnh.subscribe("input", 1, &Feature::cloudCb, this);
    if (debug_ && !approximate_)
      exact_pub_ = pnh.advertise<std_msgs::Empty>("exact_debug", 1);
    if (ready() && debug_)
      ready_pub_ = pnh.advertise<std_msgs::Empty>("ready", 1);
  }

  void cloudCb(const sensor_msgs::PointCloud2::ConstPtr& cloud) {}
  bool ready() const { return true; }

private:
  bool use_indices_, use_surface_, approximate_, debug_;
  ros::Subscriber indices_sub_, surface_sub_, surface_only_sub_, input_sub_;
  ros::Publisher exact_pub_, ready_pub_;
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "feature");
  Feature feature;
  ros::spin();
}
