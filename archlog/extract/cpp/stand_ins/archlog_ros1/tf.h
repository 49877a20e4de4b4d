// archlog stand-in for tf, tf2 and tf2_ros (ROS 1): broadcasters, listeners and the buffer.
// Written for archlog: declarations only.
#ifndef ARCHLOG_ROS1_TF_H
#define ARCHLOG_ROS1_TF_H
#include <ros/ros.h>
#include <geometry_msgs/TransformStamped.h>

namespace tf2
{
class TransformException : public std::runtime_error
{
public:
  explicit TransformException(const std::string & error);
};
class LookupException : public TransformException { public: explicit LookupException(const std::string & e); };
class ConnectivityException : public TransformException { public: explicit ConnectivityException(const std::string & e); };
class ExtrapolationException : public TransformException { public: explicit ExtrapolationException(const std::string & e); };
}  // namespace tf2

namespace tf2_ros
{
class Buffer
{
public:
  explicit Buffer(ros::Duration cache_time = ros::Duration(10.0), bool debug = false);
  geometry_msgs::TransformStamped lookupTransform(const std::string & target_frame, const std::string & source_frame,
                                                  const ros::Time & time,
                                                  const ros::Duration timeout = ros::Duration(0.0)) const;
  bool canTransform(const std::string & target_frame, const std::string & source_frame, const ros::Time & time,
                    const ros::Duration timeout = ros::Duration(0.0), std::string * errstr = nullptr) const;
  template<class T> T & transform(const T & in, T & out, const std::string & target_frame,
                                  ros::Duration timeout = ros::Duration(0.0)) const;
  template<class T> T transform(const T & in, const std::string & target_frame,
                                ros::Duration timeout = ros::Duration(0.0)) const;
};
class TransformListener
{
public:
  explicit TransformListener(Buffer & buffer, bool spin_thread = true);
  TransformListener(Buffer & buffer, const ros::NodeHandle & nh, bool spin_thread = true);
};
class TransformBroadcaster
{
public:
  TransformBroadcaster();
  void sendTransform(const geometry_msgs::TransformStamped & transform);
  void sendTransform(const std::vector<geometry_msgs::TransformStamped> & transforms);
};
class StaticTransformBroadcaster
{
public:
  StaticTransformBroadcaster();
  void sendTransform(const geometry_msgs::TransformStamped & transform);
  void sendTransform(const std::vector<geometry_msgs::TransformStamped> & transforms);
};
}  // namespace tf2_ros

namespace tf
{
typedef tf2::TransformException TransformException;
class Vector3
{
public:
  Vector3();
  Vector3(double x, double y, double z);
  double x() const;
  double y() const;
  double z() const;
};
class Quaternion
{
public:
  Quaternion();
  Quaternion(double x, double y, double z, double w);
  void setRPY(double roll, double pitch, double yaw);
};
class Transform
{
public:
  Transform();
  Transform(const Quaternion & q, const Vector3 & c = Vector3(0, 0, 0));
  Vector3 & getOrigin();
  Quaternion getRotation() const;
  void setOrigin(const Vector3 & origin);
  void setRotation(const Quaternion & q);
};
class StampedTransform : public Transform
{
public:
  StampedTransform();
  StampedTransform(const Transform & input, const ros::Time & timestamp, const std::string & frame_id,
                   const std::string & child_frame_id);
  ros::Time stamp_;
  std::string frame_id_, child_frame_id_;
};
class TransformListener
{
public:
  TransformListener(ros::Duration max_cache_time = ros::Duration(10.0), bool spin_thread = true);
  TransformListener(const ros::NodeHandle & nh, ros::Duration max_cache_time = ros::Duration(10.0),
                    bool spin_thread = true);
  void lookupTransform(const std::string & target_frame, const std::string & source_frame, const ros::Time & time,
                       StampedTransform & transform) const;
  bool waitForTransform(const std::string & target_frame, const std::string & source_frame, const ros::Time & time,
                        const ros::Duration & timeout, const ros::Duration & polling_sleep_duration = ros::Duration(0.01),
                        std::string * error_msg = nullptr) const;
  bool canTransform(const std::string & target_frame, const std::string & source_frame, const ros::Time & time,
                    std::string * error_msg = nullptr) const;
};
class TransformBroadcaster
{
public:
  TransformBroadcaster();
  void sendTransform(const StampedTransform & transform);
  void sendTransform(const geometry_msgs::TransformStamped & transform);
};
Quaternion createQuaternionFromYaw(double yaw);
double getYaw(const Quaternion & q);
}  // namespace tf
#endif
