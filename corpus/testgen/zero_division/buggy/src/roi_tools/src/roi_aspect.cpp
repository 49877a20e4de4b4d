// Aspect ratio of the detected region, in percent, for the tracker.
#include <ros/ros.h>
#include <sensor_msgs/RegionOfInterest.h>
#include <std_msgs/UInt32.h>

class AspectNode {
public:
  AspectNode() {
    pub_ = nh_.advertise<std_msgs::UInt32>("roi_aspect", 10);
    sub_ = nh_.subscribe("roi", 10, &AspectNode::onRoi, this);
  }

private:
  void onRoi(const sensor_msgs::RegionOfInterest::ConstPtr& roi) {

    std_msgs::UInt32 out;
    out.data = 100 * roi->width / roi->height;
    pub_.publish(out);
  }

  ros::NodeHandle nh_;
  ros::Publisher pub_;
  ros::Subscriber sub_;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "roi_aspect");
  AspectNode node;
  ros::spin();
  return 0;
}
