// archlog stand-in for dynamic_reconfigure's server, diagnostic_updater and interactive_markers'
// server (ROS 1). Written for archlog: declarations only.
#ifndef ARCHLOG_ROS1_TOOLS_H
#define ARCHLOG_ROS1_TOOLS_H
#include <ros/ros.h>
#include <boost/thread/recursive_mutex.hpp>
#include <diagnostic_msgs/DiagnosticStatus.h>
#include <visualization_msgs/InteractiveMarker.h>
#include <visualization_msgs/InteractiveMarkerFeedback.h>

namespace dynamic_reconfigure
{
template<class ConfigType> class Server
{
public:
  typedef boost::function<void(ConfigType &, uint32_t level)> CallbackType;
  Server(const ros::NodeHandle & nh = ros::NodeHandle("~"));
  Server(boost::recursive_mutex & mutex, const ros::NodeHandle & nh = ros::NodeHandle("~"));
  void setCallback(const CallbackType & callback);
  void clearCallback();
  void updateConfig(const ConfigType & config);
  void getConfigMax(ConfigType & config);
  void getConfigMin(ConfigType & config);
  void getConfigDefault(ConfigType & config);
  void setConfigMax(const ConfigType & config);
  void setConfigMin(const ConfigType & config);
  void setConfigDefault(const ConfigType & config);
};
}  // namespace dynamic_reconfigure

namespace diagnostic_updater
{
class DiagnosticStatusWrapper : public diagnostic_msgs::DiagnosticStatus
{
public:
  void summary(unsigned char lvl, const std::string s);
  void summary(const diagnostic_msgs::DiagnosticStatus & src);
  void summaryf(unsigned char lvl, const char * format, ...);
  void mergeSummary(unsigned char lvl, const std::string s);
  template<class T> void add(const std::string & key, const T & value);
  void addf(const std::string & key, const char * format, ...);
  void clear();
};
typedef boost::function<void(DiagnosticStatusWrapper &)> TaskFunction;
class DiagnosticTask
{
public:
  explicit DiagnosticTask(const std::string name);
  virtual ~DiagnosticTask();
  virtual void run(DiagnosticStatusWrapper & stat) = 0;
};
class Updater
{
public:
  Updater(ros::NodeHandle h = ros::NodeHandle(), ros::NodeHandle ph = ros::NodeHandle("~"),
          std::string node_name = ros::this_node::getName());
  void add(const std::string & name, TaskFunction f);
  void add(DiagnosticTask & task);
  template<class T> void add(const std::string name, T * c, void (T::*f)(DiagnosticStatusWrapper &));
  bool removeByName(const std::string name);
  void update();
  void force_update();
  double getPeriod();
  void broadcast(int lvl, const std::string msg);
  void setHardwareID(const std::string & hwid);
  void setHardwareIDf(const char * format, ...);
};
}  // namespace diagnostic_updater

namespace interactive_markers
{
class InteractiveMarkerServer
{
public:
  typedef visualization_msgs::InteractiveMarkerFeedbackConstPtr FeedbackConstPtr;
  typedef boost::function<void(const FeedbackConstPtr &)> FeedbackCallback;
  static const uint8_t DEFAULT_FEEDBACK_CB = 255;
  InteractiveMarkerServer(const std::string & topic_ns, const std::string & server_id = "",
                          bool spin_thread = false);
  ~InteractiveMarkerServer();
  void insert(const visualization_msgs::InteractiveMarker & int_marker);
  void insert(const visualization_msgs::InteractiveMarker & int_marker, FeedbackCallback feedback_cb,
              uint8_t feedback_type = DEFAULT_FEEDBACK_CB);
  bool setCallback(const std::string & name, FeedbackCallback feedback_cb,
                   uint8_t feedback_type = DEFAULT_FEEDBACK_CB);
  bool erase(const std::string & name);
  void clear();
  bool empty() const;
  std::size_t size() const;
  void applyChanges();
  bool get(std::string name, visualization_msgs::InteractiveMarker & int_marker) const;
};
}  // namespace interactive_markers
#endif
