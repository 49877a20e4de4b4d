// archlog stand-in for nodelet, nodelet_topic_tools and pluginlib's export macro (ROS 1).
// Written for archlog: declarations only.
#ifndef ARCHLOG_ROS1_NODELET_H
#define ARCHLOG_ROS1_NODELET_H
#include <ros/ros.h>

#include "archlog_ros1/print.h"

namespace nodelet
{
typedef std::map<std::string, std::string> M_string;
typedef std::vector<std::string> V_string;

class Nodelet
{
public:
  Nodelet();
  virtual ~Nodelet();
  void init(const std::string & name, const M_string & remapping_args, const V_string & my_argv,
            ros::CallbackQueueInterface * st_queue = 0, ros::CallbackQueueInterface * mt_queue = 0);

protected:
  virtual void onInit() = 0;
  const std::string & getName() const;
  ros::NodeHandle & getNodeHandle() const;
  ros::NodeHandle & getPrivateNodeHandle() const;
  ros::NodeHandle & getMTNodeHandle() const;
  ros::NodeHandle & getMTPrivateNodeHandle() const;
  ros::CallbackQueueInterface & getSTCallbackQueue() const;
  ros::CallbackQueueInterface & getMTCallbackQueue() const;
  const V_string & getMyArgv() const;
  const M_string & getRemappingArgs() const;
};

class Loader
{
public:
  explicit Loader(bool provide_ros_api = true);
  explicit Loader(const ros::NodeHandle & server_nh);
  ~Loader();
  bool load(const std::string & name, const std::string & type, const M_string & remappings,
            const V_string & my_argv);
  bool unload(const std::string & name);
  bool clear();
  std::vector<std::string> listLoadedNodelets();
};
}  // namespace nodelet

namespace nodelet_topic_tools
{
enum ConnectionStatus { NOT_INITIALIZED, NOT_SUBSCRIBED, SUBSCRIBED };

class NodeletLazy : public nodelet::Nodelet
{
protected:
  void onInit() override;
  virtual void onInitPostProcess();
  virtual void subscribe() = 0;
  virtual void unsubscribe() = 0;
  virtual void connectionCallback(const ros::SingleSubscriberPublisher & pub);
  template<class T> ros::Publisher advertise(ros::NodeHandle & nh, std::string topic, int queue_size,
                                             bool latch = false);
  boost::shared_ptr<ros::NodeHandle> nh_;
  boost::shared_ptr<ros::NodeHandle> pnh_;
  std::vector<ros::Publisher> publishers_;
  bool lazy_;
  bool verbose_connection_;
  ConnectionStatus connection_status_;
};
}  // namespace nodelet_topic_tools

namespace pluginlib
{
template<class T> class ClassLoader
{
public:
  ClassLoader(std::string package, std::string base_class,
              std::string attrib_name = std::string("plugin"), std::vector<std::string> plugin_xml_paths = {});
  boost::shared_ptr<T> createInstance(const std::string & lookup_name);
  std::unique_ptr<T> createUniqueInstance(const std::string & lookup_name);
  T * createUnmanagedInstance(const std::string & lookup_name);
  std::vector<std::string> getDeclaredClasses();
  bool isClassAvailable(const std::string & lookup_name);
};
class PluginlibException : public std::runtime_error
{
public:
  explicit PluginlibException(const std::string & error);
};
}  // namespace pluginlib

#define PLUGINLIB_EXPORT_CLASS(class_type, base_class_type) \
  namespace archlog_pluginlib { static_assert(sizeof(class_type) > 0 && sizeof(base_class_type) > 0, ""); }
#define NODELET_DEBUG(...) ARCHLOG_ROS_PRINT(__VA_ARGS__)
#define NODELET_INFO(...) ARCHLOG_ROS_PRINT(__VA_ARGS__)
#define NODELET_WARN(...) ARCHLOG_ROS_PRINT(__VA_ARGS__)
#define NODELET_ERROR(...) ARCHLOG_ROS_PRINT(__VA_ARGS__)
#define NODELET_FATAL(...) ARCHLOG_ROS_PRINT(__VA_ARGS__)
#define NODELET_DEBUG_STREAM(args) ARCHLOG_ROS_STREAM(args)
#define NODELET_INFO_STREAM(args) ARCHLOG_ROS_STREAM(args)
#define NODELET_WARN_STREAM(args) ARCHLOG_ROS_STREAM(args)
#define NODELET_ERROR_STREAM(args) ARCHLOG_ROS_STREAM(args)
#define NODELET_FATAL_STREAM(args) ARCHLOG_ROS_STREAM(args)
#define NODELET_INFO_THROTTLE(period, ...) ARCHLOG_ROS_PRINT(period, __VA_ARGS__)
#define NODELET_WARN_THROTTLE(period, ...) ARCHLOG_ROS_PRINT(period, __VA_ARGS__)
#define NODELET_ERROR_THROTTLE(period, ...) ARCHLOG_ROS_PRINT(period, __VA_ARGS__)
#define NODELET_INFO_ONCE(...) ARCHLOG_ROS_PRINT(__VA_ARGS__)
#define NODELET_WARN_ONCE(...) ARCHLOG_ROS_PRINT(__VA_ARGS__)
#endif
