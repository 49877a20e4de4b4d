// archlog stand-in for image_transport (ROS 1). Written for archlog: declarations only.
#ifndef ARCHLOG_ROS1_IMAGE_TRANSPORT_H
#define ARCHLOG_ROS1_IMAGE_TRANSPORT_H
#include <message_filters/simple_filter.h>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>

namespace image_transport
{
class TransportHints
{
public:
  TransportHints(const std::string & default_transport = "raw",
                 const ros::TransportHints & ros_hints = ros::TransportHints(),
                 const ros::NodeHandle & parameter_nh = ros::NodeHandle(),
                 const std::string & parameter_name = "image_transport");
};
class SingleSubscriberPublisher;
typedef boost::function<void(const SingleSubscriberPublisher &)> SubscriberStatusCallback;

class Publisher
{
public:
  Publisher();
  uint32_t getNumSubscribers() const;
  std::string getTopic() const;
  void publish(const sensor_msgs::Image & message) const;
  void publish(const sensor_msgs::ImageConstPtr & message) const;
  void shutdown();
  operator void *() const;
};
class CameraPublisher
{
public:
  CameraPublisher();
  uint32_t getNumSubscribers() const;
  std::string getTopic() const;
  std::string getInfoTopic() const;
  void publish(const sensor_msgs::Image & image, const sensor_msgs::CameraInfo & info) const;
  void publish(const sensor_msgs::ImageConstPtr & image, const sensor_msgs::CameraInfoConstPtr & info) const;
  void shutdown();
  operator void *() const;
};
class Subscriber
{
public:
  Subscriber();
  std::string getTopic() const;
  uint32_t getNumPublishers() const;
  void shutdown();
  operator void *() const;
};
class CameraSubscriber
{
public:
  typedef boost::function<void(const sensor_msgs::ImageConstPtr &, const sensor_msgs::CameraInfoConstPtr &)> Callback;
  CameraSubscriber();
  std::string getTopic() const;
  std::string getInfoTopic() const;
  uint32_t getNumPublishers() const;
  void shutdown();
  operator void *() const;
};

class ImageTransport
{
public:
  explicit ImageTransport(const ros::NodeHandle & nh);
  ~ImageTransport();
  Publisher advertise(const std::string & base_topic, uint32_t queue_size, bool latch = false);
  Publisher advertise(const std::string & base_topic, uint32_t queue_size,
                      const SubscriberStatusCallback & connect_cb,
                      const SubscriberStatusCallback & disconnect_cb = SubscriberStatusCallback(),
                      const ros::VoidPtr & tracked_object = ros::VoidPtr(), bool latch = false);
  Subscriber subscribe(const std::string & base_topic, uint32_t queue_size,
                       const boost::function<void(const sensor_msgs::ImageConstPtr &)> & callback,
                       const ros::VoidPtr & tracked_object = ros::VoidPtr(),
                       const TransportHints & transport_hints = TransportHints());
  Subscriber subscribe(const std::string & base_topic, uint32_t queue_size,
                       void (*fp)(const sensor_msgs::ImageConstPtr &),
                       const TransportHints & transport_hints = TransportHints());
  template<class T> Subscriber subscribe(const std::string & base_topic, uint32_t queue_size,
                                         void (T::*fp)(const sensor_msgs::ImageConstPtr &), T * obj,
                                         const TransportHints & transport_hints = TransportHints());
  template<class T> Subscriber subscribe(const std::string & base_topic, uint32_t queue_size,
                                         void (T::*fp)(const sensor_msgs::ImageConstPtr &),
                                         const boost::shared_ptr<T> & obj,
                                         const TransportHints & transport_hints = TransportHints());
  CameraPublisher advertiseCamera(const std::string & base_topic, uint32_t queue_size, bool latch = false);
  CameraSubscriber subscribeCamera(const std::string & base_topic, uint32_t queue_size,
                                   const CameraSubscriber::Callback & callback,
                                   const ros::VoidPtr & tracked_object = ros::VoidPtr(),
                                   const TransportHints & transport_hints = TransportHints());
  CameraSubscriber subscribeCamera(const std::string & base_topic, uint32_t queue_size,
                                   void (*fp)(const sensor_msgs::ImageConstPtr &,
                                              const sensor_msgs::CameraInfoConstPtr &),
                                   const TransportHints & transport_hints = TransportHints());
  template<class T> CameraSubscriber subscribeCamera(const std::string & base_topic, uint32_t queue_size,
                                                     void (T::*fp)(const sensor_msgs::ImageConstPtr &,
                                                                   const sensor_msgs::CameraInfoConstPtr &),
                                                     T * obj,
                                                     const TransportHints & transport_hints = TransportHints());
  template<class T> CameraSubscriber subscribeCamera(const std::string & base_topic, uint32_t queue_size,
                                                     void (T::*fp)(const sensor_msgs::ImageConstPtr &,
                                                                   const sensor_msgs::CameraInfoConstPtr &),
                                                     const boost::shared_ptr<T> & obj,
                                                     const TransportHints & transport_hints = TransportHints());
};

class SubscriberFilter : public message_filters::SimpleFilter<sensor_msgs::Image>
{
public:
  SubscriberFilter();
  SubscriberFilter(ImageTransport & it, const std::string & base_topic, uint32_t queue_size,
                   const TransportHints & transport_hints = TransportHints());
  void subscribe(ImageTransport & it, const std::string & base_topic, uint32_t queue_size,
                 const TransportHints & transport_hints = TransportHints());
  void unsubscribe();
  std::string getTopic() const;
};
}  // namespace image_transport
#endif
