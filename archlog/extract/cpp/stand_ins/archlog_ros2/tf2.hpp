// archlog stand-in for tf2 and tf2_geometry_msgs (ROS 2): time, stamped data, conversions.
// tf2's LinearMath and exceptions are the same in ROS 1, whose headers are used when installed.
#ifndef ARCHLOG_ROS2_TF2_HPP_
#define ARCHLOG_ROS2_TF2_HPP_

#include "archlog_ros2/rclcpp.hpp"
#include "geometry_msgs/msg/point_stamped.hpp"
#include "geometry_msgs/msg/pose_stamped.hpp"
#include "geometry_msgs/msg/pose_with_covariance_stamped.hpp"
#include "geometry_msgs/msg/quaternion_stamped.hpp"
#include "geometry_msgs/msg/transform_stamped.hpp"
#include "geometry_msgs/msg/twist_stamped.hpp"
#include "geometry_msgs/msg/vector3_stamped.hpp"

#if __has_include(<tf2/LinearMath/Transform.h>)
#include <tf2/LinearMath/Matrix3x3.h>
#include <tf2/LinearMath/Quaternion.h>
#include <tf2/LinearMath/Transform.h>
#include <tf2/LinearMath/Vector3.h>
#include <tf2/exceptions.h>
#endif

namespace tf2
{
class BufferCore;
using Duration = std::chrono::nanoseconds;
using TimePoint = std::chrono::time_point<std::chrono::system_clock, Duration>;
using IDuration = std::chrono::duration<int, std::nano>;
static const TimePoint TimePointZero = TimePoint(Duration::zero());
Duration durationFromSec(double t_sec);
TimePoint timeFromSec(double t_sec);
double timeToSec(const TimePoint & timepoint);
double durationToSec(const tf2::Duration & input);
std::string displayTimePoint(const TimePoint & stamp);

template<typename T>
class Stamped : public T
{
public:
  TimePoint stamp_;
  std::string frame_id_;
  Stamped();
  Stamped(const T & input, const TimePoint & timestamp, const std::string & frame_id);
  void setData(const T & input);
};
template<typename T>
class WithCovarianceStamped : public T
{
public:
  TimePoint stamp_;
  std::string frame_id_;
  std::array<double, 36> cov_mat_;
  WithCovarianceStamped();
  WithCovarianceStamped(
    const T & input, const TimePoint & timestamp, const std::string & frame_id, const std::array<double, 36> & cov);
  void setData(const T & input);
};

template<class A>
double getYaw(const A & a);
template<class A>
void getEulerYPR(const A & a, double & yaw, double & pitch, double & roll);
template<class A>
A getTransformIdentity();
template<class T>
const TimePoint & getTimestamp(const T & t);
template<class T>
const std::string & getFrameId(const T & t);
template<class T>
void doTransform(const T & data_in, T & data_out, const geometry_msgs::msg::TransformStamped & transform);
template<class A, class B>
void doTransform(const A & data_in, B & data_out, const geometry_msgs::msg::TransformStamped & transform);
template<class A, class B>
void convert(const A & a, B & b);
template<class A, class B>
void fromMsg(const A & a, B & b);
template<class A, class B>
B & toMsg(const A & a, B & b);

#if __has_include(<tf2/LinearMath/Transform.h>)
// tf2_geometry_msgs
geometry_msgs::msg::Quaternion toMsg(const tf2::Quaternion & in);
geometry_msgs::msg::Vector3 toMsg(const tf2::Vector3 & in);
geometry_msgs::msg::Transform toMsg(const tf2::Transform & in);
geometry_msgs::msg::Point & toMsg(const tf2::Vector3 & in, geometry_msgs::msg::Point & out);
geometry_msgs::msg::Pose & toMsg(const tf2::Transform & in, geometry_msgs::msg::Pose & out);
geometry_msgs::msg::TransformStamped toMsg(const tf2::Stamped<tf2::Transform> & in);
geometry_msgs::msg::PoseStamped toMsg(const tf2::Stamped<tf2::Transform> & in, geometry_msgs::msg::PoseStamped & out);
void fromMsg(const geometry_msgs::msg::Quaternion & in, tf2::Quaternion & out);
void fromMsg(const geometry_msgs::msg::Vector3 & in, tf2::Vector3 & out);
void fromMsg(const geometry_msgs::msg::Point & in, tf2::Vector3 & out);
void fromMsg(const geometry_msgs::msg::Transform & in, tf2::Transform & out);
void fromMsg(const geometry_msgs::msg::Pose & in, tf2::Transform & out);
void fromMsg(const geometry_msgs::msg::TransformStamped & in, tf2::Stamped<tf2::Transform> & out);
void fromMsg(const geometry_msgs::msg::PoseStamped & in, tf2::Stamped<tf2::Transform> & out);
#endif
}  // namespace tf2

#endif  // ARCHLOG_ROS2_TF2_HPP_
