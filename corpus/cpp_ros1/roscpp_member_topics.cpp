// Topic names held in data members that the constructor's member initializer list sets (pcl_ros's
// convert_pointcloud_to_image): the ports are named by those values.
#include <ros/ros.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/PointCloud2.h>
#include <string>

class CloudToImage
{
public:
  CloudToImage() : cloud_topic_("input"), image_topic_("output")
  {
    sub_ = nh_.subscribe(cloud_topic_, 30, &CloudToImage::convert, this);
    pub_ = nh_.advertise<sensor_msgs::Image>(image_topic_, 30);
  }

private:
  ros::NodeHandle nh_;
  std::string cloud_topic_;
  std::string image_topic_;
  ros::Subscriber sub_;
  ros::Publisher pub_;

  void convert(const sensor_msgs::PointCloud2ConstPtr& cloud)
  {
    pub_.publish(sensor_msgs::Image());
  }
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "cloud_to_image");
  CloudToImage node;
  ros::spin();
}
