// A standalone executable that runs the blur nodelet in its own process, named <node>_blur.
#include <nodelet/loader.h>
#include <ros/ros.h>

int main(int argc, char** argv)
{
  ros::init(argc, argv, "pipeline");
  nodelet::Loader manager(false);
  nodelet::M_string remappings;
  nodelet::V_string my_argv;
  manager.load(ros::this_node::getName() + "_blur", "camera_proc/Blur", remappings, my_argv);
  ros::spin();
  return 0;
}
