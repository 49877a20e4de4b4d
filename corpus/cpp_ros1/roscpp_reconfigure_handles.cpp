// dynamic_reconfigure servers: one given a mutex and then its handle (image_proc's nodelets), so
// it serves under that handle's namespace; one built without a handle, which serves in
// NodeHandle("~") of the process.
#include <boost/thread/recursive_mutex.hpp>
#include <dynamic_reconfigure/TestConfig.h>
#include <dynamic_reconfigure/server.h>
#include <ros/ros.h>

int main(int argc, char** argv)
{
  ros::init(argc, argv, "tuned");
  ros::NodeHandle camera_nh("~camera");
  boost::recursive_mutex mutex;
  dynamic_reconfigure::Server<dynamic_reconfigure_test::TestConfig> camera(mutex, camera_nh);
  dynamic_reconfigure::Server<dynamic_reconfigure_test::TestConfig> process;
  ros::spin();
}
