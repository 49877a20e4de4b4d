// archlog stand-in for sensor_msgs' C++ helpers (ROS 2): point cloud iterators, image encodings.
#ifndef ARCHLOG_ROS2_SENSOR_MSGS_HPP_
#define ARCHLOG_ROS2_SENSOR_MSGS_HPP_

#include <string>

#include "sensor_msgs/msg/point_cloud2.hpp"
#include "sensor_msgs/msg/point_field.hpp"

namespace sensor_msgs
{
namespace image_encodings
{
const char RGB8[] = "rgb8";
const char RGBA8[] = "rgba8";
const char RGB16[] = "rgb16";
const char BGR8[] = "bgr8";
const char BGRA8[] = "bgra8";
const char BGR16[] = "bgr16";
const char MONO8[] = "mono8";
const char MONO16[] = "mono16";
const char TYPE_8UC1[] = "8UC1";
const char TYPE_8UC3[] = "8UC3";
const char TYPE_16UC1[] = "16UC1";
const char TYPE_32FC1[] = "32FC1";
const char YUV422[] = "yuv422";
bool isColor(const std::string & encoding);
bool isMono(const std::string & encoding);
bool hasAlpha(const std::string & encoding);
int numChannels(const std::string & encoding);
int bitDepth(const std::string & encoding);
}  // namespace image_encodings

class PointCloud2Modifier
{
public:
  explicit PointCloud2Modifier(sensor_msgs::msg::PointCloud2 & cloud_msg);
  size_t size() const;
  void reserve(size_t size);
  void resize(size_t size);
  void clear();
  void setPointCloud2Fields(int n_fields, ...);
  void setPointCloud2FieldsByString(int n_fields, ...);
};

template<typename T>
class PointCloud2ConstIterator
{
public:
  PointCloud2ConstIterator(const sensor_msgs::msg::PointCloud2 & cloud_msg, const std::string & field_name);
  const T & operator*() const;
  const T & operator[](size_t i) const;
  PointCloud2ConstIterator & operator++();
  PointCloud2ConstIterator operator+(int i);
  PointCloud2ConstIterator & operator+=(int i);
  bool operator!=(const PointCloud2ConstIterator & iter) const;
  PointCloud2ConstIterator end() const;
};

template<typename T>
class PointCloud2Iterator
{
public:
  PointCloud2Iterator(sensor_msgs::msg::PointCloud2 & cloud_msg, const std::string & field_name);
  T & operator*() const;
  T & operator[](size_t i) const;
  PointCloud2Iterator & operator++();
  PointCloud2Iterator operator+(int i);
  PointCloud2Iterator & operator+=(int i);
  bool operator!=(const PointCloud2Iterator & iter) const;
  PointCloud2Iterator end() const;
};
}  // namespace sensor_msgs

#endif  // ARCHLOG_ROS2_SENSOR_MSGS_HPP_
