// archlog stand-in for rclcpp, rmw and rcl (ROS 2), used only where their headers are not
// installed. Declarations of the API archlog reads, under rclcpp's qualified names and with its
// signatures, so that the walker sees the AST it would see with the real headers. Nothing here is
// ever compiled into a program: there are no definitions.
#ifndef ARCHLOG_ROS2_RCLCPP_HPP_
#define ARCHLOG_ROS2_RCLCPP_HPP_

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cinttypes>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <future>
#include <iostream>
#include <limits>
#include <list>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <tuple>
#include <type_traits>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#if __has_include("rcutils/logging_macros.h")
#include "rcutils/logging.h"
#include "rcutils/logging_macros.h"
#endif

#include "builtin_interfaces/msg/duration.hpp"
#include "builtin_interfaces/msg/time.hpp"
#include "rcl_interfaces/msg/list_parameters_result.hpp"
#include "rcl_interfaces/msg/parameter_descriptor.hpp"
#include "rcl_interfaces/msg/set_parameters_result.hpp"

// rclcpp/version.h: the API declared here is Jazzy's
#define RCLCPP_VERSION_MAJOR (28)
#define RCLCPP_VERSION_MINOR (1)
#define RCLCPP_VERSION_PATCH (0)
#define RCLCPP_VERSION_STR "28.1.0"
#define RCLCPP_VERSION_GTE(major, minor, patch) ( \
    (major < RCLCPP_VERSION_MAJOR) ? true : \
    (major > RCLCPP_VERSION_MAJOR) ? false : \
    (minor < RCLCPP_VERSION_MINOR) ? true : \
    (minor > RCLCPP_VERSION_MINOR) ? false : \
    (patch < RCLCPP_VERSION_PATCH) ? true : \
    (patch > RCLCPP_VERSION_PATCH) ? false : true)

#define RCLCPP_PUBLIC
#define RCLCPP_LOCAL
#define RCLCPP_PUBLIC_TYPE
#define RCLCPP_SMART_PTR_ALIASES_ONLY(...) \
  using SharedPtr = std::shared_ptr<__VA_ARGS__>; \
  using ConstSharedPtr = std::shared_ptr<const __VA_ARGS__>; \
  using WeakPtr = std::weak_ptr<__VA_ARGS__>; \
  using ConstWeakPtr = std::weak_ptr<const __VA_ARGS__>; \
  using UniquePtr = std::unique_ptr<__VA_ARGS__>;
#define RCLCPP_SMART_PTR_DEFINITIONS(...) \
  RCLCPP_SMART_PTR_ALIASES_ONLY(__VA_ARGS__) \
  template<typename ... Args> static std::shared_ptr<__VA_ARGS__> make_shared(Args && ... args); \
  template<typename ... Args> static std::unique_ptr<__VA_ARGS__> make_unique(Args && ... args);
#define RCLCPP_SMART_PTR_DEFINITIONS_NOT_COPYABLE(...) RCLCPP_SMART_PTR_DEFINITIONS(__VA_ARGS__)
#define RCLCPP_DISABLE_COPY(...) \
  __VA_ARGS__(const __VA_ARGS__ &) = delete; \
  __VA_ARGS__ & operator=(const __VA_ARGS__ &) = delete;

// ---- rmw and rcl (C) ------------------------------------------------------------------------
extern "C"
{
enum rmw_qos_history_policy_e
{
  RMW_QOS_POLICY_HISTORY_SYSTEM_DEFAULT,
  RMW_QOS_POLICY_HISTORY_KEEP_LAST,
  RMW_QOS_POLICY_HISTORY_KEEP_ALL,
  RMW_QOS_POLICY_HISTORY_UNKNOWN
};
typedef enum rmw_qos_history_policy_e rmw_qos_history_policy_t;
enum rmw_qos_reliability_policy_e
{
  RMW_QOS_POLICY_RELIABILITY_SYSTEM_DEFAULT,
  RMW_QOS_POLICY_RELIABILITY_RELIABLE,
  RMW_QOS_POLICY_RELIABILITY_BEST_EFFORT,
  RMW_QOS_POLICY_RELIABILITY_UNKNOWN,
  RMW_QOS_POLICY_RELIABILITY_BEST_AVAILABLE
};
typedef enum rmw_qos_reliability_policy_e rmw_qos_reliability_policy_t;
enum rmw_qos_durability_policy_e
{
  RMW_QOS_POLICY_DURABILITY_SYSTEM_DEFAULT,
  RMW_QOS_POLICY_DURABILITY_TRANSIENT_LOCAL,
  RMW_QOS_POLICY_DURABILITY_VOLATILE,
  RMW_QOS_POLICY_DURABILITY_UNKNOWN,
  RMW_QOS_POLICY_DURABILITY_BEST_AVAILABLE
};
typedef enum rmw_qos_durability_policy_e rmw_qos_durability_policy_t;
enum rmw_qos_liveliness_policy_e
{
  RMW_QOS_POLICY_LIVELINESS_SYSTEM_DEFAULT = 0,
  RMW_QOS_POLICY_LIVELINESS_AUTOMATIC = 1,
  RMW_QOS_POLICY_LIVELINESS_MANUAL_BY_NODE = 2,
  RMW_QOS_POLICY_LIVELINESS_MANUAL_BY_TOPIC = 3,
  RMW_QOS_POLICY_LIVELINESS_UNKNOWN = 4,
  RMW_QOS_POLICY_LIVELINESS_BEST_AVAILABLE = 5
};
typedef enum rmw_qos_liveliness_policy_e rmw_qos_liveliness_policy_t;
typedef struct rmw_time_s
{
  uint64_t sec;
  uint64_t nsec;
} rmw_time_t;
#define RMW_DURATION_INFINITE {9223372036LL, 854775807LL}
#define RMW_DURATION_UNSPECIFIED {0LL, 0LL}
#define RMW_QOS_DEADLINE_DEFAULT RMW_DURATION_UNSPECIFIED
#define RMW_QOS_LIFESPAN_DEFAULT RMW_DURATION_UNSPECIFIED
#define RMW_QOS_LIVELINESS_LEASE_DURATION_DEFAULT RMW_DURATION_UNSPECIFIED
#define RMW_QOS_DEADLINE_BEST_AVAILABLE {9223372036LL, 854775806LL}
#define RMW_QOS_LIVELINESS_LEASE_DURATION_BEST_AVAILABLE {9223372036LL, 854775806LL}
#define RMW_QOS_POLICY_DEPTH_SYSTEM_DEFAULT 0
typedef struct rmw_qos_profile_s
{
  enum rmw_qos_history_policy_e history;
  size_t depth;
  enum rmw_qos_reliability_policy_e reliability;
  enum rmw_qos_durability_policy_e durability;
  struct rmw_time_s deadline;
  struct rmw_time_s lifespan;
  enum rmw_qos_liveliness_policy_e liveliness;
  struct rmw_time_s liveliness_lease_duration;
  bool avoid_ros_namespace_conventions;
} rmw_qos_profile_t;
static const rmw_qos_profile_t rmw_qos_profile_sensor_data = {
  RMW_QOS_POLICY_HISTORY_KEEP_LAST, 5, RMW_QOS_POLICY_RELIABILITY_BEST_EFFORT,
  RMW_QOS_POLICY_DURABILITY_VOLATILE, RMW_QOS_DEADLINE_DEFAULT, RMW_QOS_LIFESPAN_DEFAULT,
  RMW_QOS_POLICY_LIVELINESS_SYSTEM_DEFAULT, RMW_QOS_LIVELINESS_LEASE_DURATION_DEFAULT, false};
static const rmw_qos_profile_t rmw_qos_profile_parameters = {
  RMW_QOS_POLICY_HISTORY_KEEP_LAST, 1000, RMW_QOS_POLICY_RELIABILITY_RELIABLE,
  RMW_QOS_POLICY_DURABILITY_VOLATILE, RMW_QOS_DEADLINE_DEFAULT, RMW_QOS_LIFESPAN_DEFAULT,
  RMW_QOS_POLICY_LIVELINESS_SYSTEM_DEFAULT, RMW_QOS_LIVELINESS_LEASE_DURATION_DEFAULT, false};
static const rmw_qos_profile_t rmw_qos_profile_default = {
  RMW_QOS_POLICY_HISTORY_KEEP_LAST, 10, RMW_QOS_POLICY_RELIABILITY_RELIABLE,
  RMW_QOS_POLICY_DURABILITY_VOLATILE, RMW_QOS_DEADLINE_DEFAULT, RMW_QOS_LIFESPAN_DEFAULT,
  RMW_QOS_POLICY_LIVELINESS_SYSTEM_DEFAULT, RMW_QOS_LIVELINESS_LEASE_DURATION_DEFAULT, false};
static const rmw_qos_profile_t rmw_qos_profile_services_default = {
  RMW_QOS_POLICY_HISTORY_KEEP_LAST, 10, RMW_QOS_POLICY_RELIABILITY_RELIABLE,
  RMW_QOS_POLICY_DURABILITY_VOLATILE, RMW_QOS_DEADLINE_DEFAULT, RMW_QOS_LIFESPAN_DEFAULT,
  RMW_QOS_POLICY_LIVELINESS_SYSTEM_DEFAULT, RMW_QOS_LIVELINESS_LEASE_DURATION_DEFAULT, false};
static const rmw_qos_profile_t rmw_qos_profile_parameter_events = {
  RMW_QOS_POLICY_HISTORY_KEEP_LAST, 1000, RMW_QOS_POLICY_RELIABILITY_RELIABLE,
  RMW_QOS_POLICY_DURABILITY_VOLATILE, RMW_QOS_DEADLINE_DEFAULT, RMW_QOS_LIFESPAN_DEFAULT,
  RMW_QOS_POLICY_LIVELINESS_SYSTEM_DEFAULT, RMW_QOS_LIVELINESS_LEASE_DURATION_DEFAULT, false};
static const rmw_qos_profile_t rmw_qos_profile_system_default = {
  RMW_QOS_POLICY_HISTORY_SYSTEM_DEFAULT, RMW_QOS_POLICY_DEPTH_SYSTEM_DEFAULT,
  RMW_QOS_POLICY_RELIABILITY_SYSTEM_DEFAULT, RMW_QOS_POLICY_DURABILITY_SYSTEM_DEFAULT,
  RMW_QOS_DEADLINE_DEFAULT, RMW_QOS_LIFESPAN_DEFAULT, RMW_QOS_POLICY_LIVELINESS_SYSTEM_DEFAULT,
  RMW_QOS_LIVELINESS_LEASE_DURATION_DEFAULT, false};
static const rmw_qos_profile_t rmw_qos_profile_best_available = {
  RMW_QOS_POLICY_HISTORY_KEEP_LAST, 10, RMW_QOS_POLICY_RELIABILITY_BEST_AVAILABLE,
  RMW_QOS_POLICY_DURABILITY_BEST_AVAILABLE, RMW_QOS_DEADLINE_BEST_AVAILABLE, RMW_QOS_LIFESPAN_DEFAULT,
  RMW_QOS_POLICY_LIVELINESS_BEST_AVAILABLE, RMW_QOS_LIVELINESS_LEASE_DURATION_BEST_AVAILABLE, false};
static const rmw_qos_profile_t rmw_qos_profile_unknown = {
  RMW_QOS_POLICY_HISTORY_UNKNOWN, RMW_QOS_POLICY_DEPTH_SYSTEM_DEFAULT, RMW_QOS_POLICY_RELIABILITY_UNKNOWN,
  RMW_QOS_POLICY_DURABILITY_UNKNOWN, RMW_QOS_DEADLINE_DEFAULT, RMW_QOS_LIFESPAN_DEFAULT,
  RMW_QOS_POLICY_LIVELINESS_UNKNOWN, RMW_QOS_LIVELINESS_LEASE_DURATION_DEFAULT, false};
static const rmw_qos_profile_t rcl_qos_profile_rosout_default = {
  RMW_QOS_POLICY_HISTORY_KEEP_LAST, 1000, RMW_QOS_POLICY_RELIABILITY_RELIABLE,
  RMW_QOS_POLICY_DURABILITY_TRANSIENT_LOCAL, RMW_QOS_DEADLINE_DEFAULT, {10, 0},
  RMW_QOS_POLICY_LIVELINESS_SYSTEM_DEFAULT, RMW_QOS_LIVELINESS_LEASE_DURATION_DEFAULT, false};
typedef struct rmw_request_id_s
{
  int8_t writer_guid[16];
  int64_t sequence_number;
} rmw_request_id_t;
typedef enum rcl_clock_type_e
{
  RCL_CLOCK_UNINITIALIZED = 0,
  RCL_ROS_TIME,
  RCL_SYSTEM_TIME,
  RCL_STEADY_TIME
} rcl_clock_type_t;
typedef int64_t rcl_duration_value_t;
typedef enum rcl_service_introspection_state_e
{
  RCL_SERVICE_INTROSPECTION_OFF,
  RCL_SERVICE_INTROSPECTION_METADATA,
  RCL_SERVICE_INTROSPECTION_CONTENTS
} rcl_service_introspection_state_t;
typedef struct rcl_node_s rcl_node_t;
}

#define RCLCPP_DEBUG(...) ((void)0)
#define RCLCPP_DEBUG_ONCE(...) ((void)0)
#define RCLCPP_DEBUG_EXPRESSION(...) ((void)0)
#define RCLCPP_DEBUG_FUNCTION(...) ((void)0)
#define RCLCPP_DEBUG_SKIPFIRST(...) ((void)0)
#define RCLCPP_DEBUG_THROTTLE(...) ((void)0)
#define RCLCPP_DEBUG_SKIPFIRST_THROTTLE(...) ((void)0)
#define RCLCPP_DEBUG_STREAM(...) ((void)0)
#define RCLCPP_DEBUG_STREAM_ONCE(...) ((void)0)
#define RCLCPP_DEBUG_STREAM_EXPRESSION(...) ((void)0)
#define RCLCPP_DEBUG_STREAM_FUNCTION(...) ((void)0)
#define RCLCPP_DEBUG_STREAM_SKIPFIRST(...) ((void)0)
#define RCLCPP_DEBUG_STREAM_THROTTLE(...) ((void)0)
#define RCLCPP_DEBUG_STREAM_SKIPFIRST_THROTTLE(...) ((void)0)
#define RCLCPP_INFO(...) ((void)0)
#define RCLCPP_INFO_ONCE(...) ((void)0)
#define RCLCPP_INFO_EXPRESSION(...) ((void)0)
#define RCLCPP_INFO_FUNCTION(...) ((void)0)
#define RCLCPP_INFO_SKIPFIRST(...) ((void)0)
#define RCLCPP_INFO_THROTTLE(...) ((void)0)
#define RCLCPP_INFO_SKIPFIRST_THROTTLE(...) ((void)0)
#define RCLCPP_INFO_STREAM(...) ((void)0)
#define RCLCPP_INFO_STREAM_ONCE(...) ((void)0)
#define RCLCPP_INFO_STREAM_EXPRESSION(...) ((void)0)
#define RCLCPP_INFO_STREAM_FUNCTION(...) ((void)0)
#define RCLCPP_INFO_STREAM_SKIPFIRST(...) ((void)0)
#define RCLCPP_INFO_STREAM_THROTTLE(...) ((void)0)
#define RCLCPP_INFO_STREAM_SKIPFIRST_THROTTLE(...) ((void)0)
#define RCLCPP_WARN(...) ((void)0)
#define RCLCPP_WARN_ONCE(...) ((void)0)
#define RCLCPP_WARN_EXPRESSION(...) ((void)0)
#define RCLCPP_WARN_FUNCTION(...) ((void)0)
#define RCLCPP_WARN_SKIPFIRST(...) ((void)0)
#define RCLCPP_WARN_THROTTLE(...) ((void)0)
#define RCLCPP_WARN_SKIPFIRST_THROTTLE(...) ((void)0)
#define RCLCPP_WARN_STREAM(...) ((void)0)
#define RCLCPP_WARN_STREAM_ONCE(...) ((void)0)
#define RCLCPP_WARN_STREAM_EXPRESSION(...) ((void)0)
#define RCLCPP_WARN_STREAM_FUNCTION(...) ((void)0)
#define RCLCPP_WARN_STREAM_SKIPFIRST(...) ((void)0)
#define RCLCPP_WARN_STREAM_THROTTLE(...) ((void)0)
#define RCLCPP_WARN_STREAM_SKIPFIRST_THROTTLE(...) ((void)0)
#define RCLCPP_ERROR(...) ((void)0)
#define RCLCPP_ERROR_ONCE(...) ((void)0)
#define RCLCPP_ERROR_EXPRESSION(...) ((void)0)
#define RCLCPP_ERROR_FUNCTION(...) ((void)0)
#define RCLCPP_ERROR_SKIPFIRST(...) ((void)0)
#define RCLCPP_ERROR_THROTTLE(...) ((void)0)
#define RCLCPP_ERROR_SKIPFIRST_THROTTLE(...) ((void)0)
#define RCLCPP_ERROR_STREAM(...) ((void)0)
#define RCLCPP_ERROR_STREAM_ONCE(...) ((void)0)
#define RCLCPP_ERROR_STREAM_EXPRESSION(...) ((void)0)
#define RCLCPP_ERROR_STREAM_FUNCTION(...) ((void)0)
#define RCLCPP_ERROR_STREAM_SKIPFIRST(...) ((void)0)
#define RCLCPP_ERROR_STREAM_THROTTLE(...) ((void)0)
#define RCLCPP_ERROR_STREAM_SKIPFIRST_THROTTLE(...) ((void)0)
#define RCLCPP_FATAL(...) ((void)0)
#define RCLCPP_FATAL_ONCE(...) ((void)0)
#define RCLCPP_FATAL_EXPRESSION(...) ((void)0)
#define RCLCPP_FATAL_FUNCTION(...) ((void)0)
#define RCLCPP_FATAL_SKIPFIRST(...) ((void)0)
#define RCLCPP_FATAL_THROTTLE(...) ((void)0)
#define RCLCPP_FATAL_SKIPFIRST_THROTTLE(...) ((void)0)
#define RCLCPP_FATAL_STREAM(...) ((void)0)
#define RCLCPP_FATAL_STREAM_ONCE(...) ((void)0)
#define RCLCPP_FATAL_STREAM_EXPRESSION(...) ((void)0)
#define RCLCPP_FATAL_STREAM_FUNCTION(...) ((void)0)
#define RCLCPP_FATAL_STREAM_SKIPFIRST(...) ((void)0)
#define RCLCPP_FATAL_STREAM_THROTTLE(...) ((void)0)
#define RCLCPP_FATAL_STREAM_SKIPFIRST_THROTTLE(...) ((void)0)

namespace rclcpp
{
// ---- time -----------------------------------------------------------------------------------
class Duration
{
public:
  Duration(int32_t seconds, uint32_t nanoseconds);
  explicit Duration(std::chrono::nanoseconds nanoseconds);
  template<class Rep, class Period>
  Duration(const std::chrono::duration<Rep, Period> & duration);  // NOLINT
  Duration(const builtin_interfaces::msg::Duration & duration_msg);  // NOLINT
  explicit Duration(const rmw_time_t & duration);
  Duration(const Duration & rhs);
  Duration & operator=(const Duration & rhs);
  operator builtin_interfaces::msg::Duration() const;
  bool operator==(const Duration & rhs) const;
  bool operator!=(const Duration & rhs) const;
  bool operator<(const Duration & rhs) const;
  bool operator<=(const Duration & rhs) const;
  bool operator>(const Duration & rhs) const;
  bool operator>=(const Duration & rhs) const;
  Duration operator+(const Duration & rhs) const;
  Duration operator-(const Duration & rhs) const;
  Duration operator*(double scale) const;
  Duration & operator+=(const Duration & rhs);
  Duration & operator-=(const Duration & rhs);
  Duration & operator*=(double scale);
  static Duration max();
  static Duration from_seconds(double seconds);
  static Duration from_nanoseconds(rcl_duration_value_t nanoseconds);
  static Duration from_rmw_time(rmw_time_t duration);
  rcl_duration_value_t nanoseconds() const;
  double seconds() const;
  template<class DurationT>
  DurationT to_chrono() const;
  rmw_time_t to_rmw_time() const;
};

class Time
{
public:
  Time(int32_t seconds, uint32_t nanoseconds, rcl_clock_type_t clock_type = RCL_SYSTEM_TIME);
  explicit Time(int64_t nanoseconds = 0, rcl_clock_type_t clock = RCL_SYSTEM_TIME);
  Time(const Time & rhs);
  Time(const builtin_interfaces::msg::Time & time_msg, rcl_clock_type_t clock_type = RCL_ROS_TIME);  // NOLINT
  Time & operator=(const Time & rhs);
  Time & operator=(const builtin_interfaces::msg::Time & time_msg);
  operator builtin_interfaces::msg::Time() const;
  bool operator==(const Time & rhs) const;
  bool operator!=(const Time & rhs) const;
  bool operator<(const Time & rhs) const;
  bool operator<=(const Time & rhs) const;
  bool operator>(const Time & rhs) const;
  bool operator>=(const Time & rhs) const;
  Time operator+(const Duration & rhs) const;
  Duration operator-(const Time & rhs) const;
  Time operator-(const Duration & rhs) const;
  Time & operator+=(const Duration & rhs);
  Time & operator-=(const Duration & rhs);
  int64_t nanoseconds() const;
  double seconds() const;
  rcl_clock_type_t get_clock_type() const;
  static Time max(rcl_clock_type_t clock_type = RCL_SYSTEM_TIME);
};

struct PreShutdownCallbackHandle
{
  std::weak_ptr<std::function<void()>> callback;
};
struct OnShutdownCallbackHandle
{
  std::weak_ptr<std::function<void()>> callback;
};

class Context
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Context)
  bool is_valid() const;
  bool shutdown(const std::string & reason);
  OnShutdownCallbackHandle add_on_shutdown_callback(std::function<void()> callback);
  bool remove_on_shutdown_callback(const OnShutdownCallbackHandle & callback_handle);
  PreShutdownCallbackHandle add_pre_shutdown_callback(std::function<void()> callback);
  bool remove_pre_shutdown_callback(const PreShutdownCallbackHandle & callback_handle);
};

class Clock
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Clock)
  explicit Clock(rcl_clock_type_t clock_type = RCL_SYSTEM_TIME);
  Time now() const;
  bool sleep_until(Time until, Context::SharedPtr context = nullptr);
  bool sleep_for(Duration rel_time, Context::SharedPtr context = nullptr);
  bool ros_time_is_active();
  rcl_clock_type_t get_clock_type() const;
};

class Rate
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Rate)
  explicit Rate(const double rate, Clock::SharedPtr clock = std::make_shared<Clock>(RCL_SYSTEM_TIME));
  explicit Rate(const Duration & period, Clock::SharedPtr clock = std::make_shared<Clock>(RCL_SYSTEM_TIME));
  virtual bool sleep();
  virtual void reset();
  std::chrono::nanoseconds period() const;
};

class WallRate : public Rate
{
public:
  explicit WallRate(const double rate);
  explicit WallRate(const Duration & period);
};

bool sleep_for(const std::chrono::nanoseconds & nanoseconds, Context::SharedPtr context = nullptr);

// ---- logging --------------------------------------------------------------------------------
class Logger
{
public:
  enum class Level { Unset, Debug, Info, Warn, Error, Fatal };
  const char * get_name() const;
  Logger get_child(const std::string & suffix);
  void set_level(Level level);
};
Logger get_logger(const std::string & name);

// ---- QoS (rclcpp/qos.hpp) --------------------------------------------------------------------
enum class HistoryPolicy
{
  KeepLast = RMW_QOS_POLICY_HISTORY_KEEP_LAST,
  KeepAll = RMW_QOS_POLICY_HISTORY_KEEP_ALL,
  SystemDefault = RMW_QOS_POLICY_HISTORY_SYSTEM_DEFAULT,
  Unknown = RMW_QOS_POLICY_HISTORY_UNKNOWN,
};
enum class ReliabilityPolicy
{
  BestEffort = RMW_QOS_POLICY_RELIABILITY_BEST_EFFORT,
  Reliable = RMW_QOS_POLICY_RELIABILITY_RELIABLE,
  SystemDefault = RMW_QOS_POLICY_RELIABILITY_SYSTEM_DEFAULT,
  BestAvailable = RMW_QOS_POLICY_RELIABILITY_BEST_AVAILABLE,
  Unknown = RMW_QOS_POLICY_RELIABILITY_UNKNOWN,
};
enum class DurabilityPolicy
{
  Volatile = RMW_QOS_POLICY_DURABILITY_VOLATILE,
  TransientLocal = RMW_QOS_POLICY_DURABILITY_TRANSIENT_LOCAL,
  SystemDefault = RMW_QOS_POLICY_DURABILITY_SYSTEM_DEFAULT,
  BestAvailable = RMW_QOS_POLICY_DURABILITY_BEST_AVAILABLE,
  Unknown = RMW_QOS_POLICY_DURABILITY_UNKNOWN,
};
enum class LivelinessPolicy
{
  Automatic = RMW_QOS_POLICY_LIVELINESS_AUTOMATIC,
  ManualByTopic = RMW_QOS_POLICY_LIVELINESS_MANUAL_BY_TOPIC,
  SystemDefault = RMW_QOS_POLICY_LIVELINESS_SYSTEM_DEFAULT,
  BestAvailable = RMW_QOS_POLICY_LIVELINESS_BEST_AVAILABLE,
  Unknown = RMW_QOS_POLICY_LIVELINESS_UNKNOWN,
};

struct QoSInitialization
{
  rmw_qos_history_policy_t history_policy;
  size_t depth;
  QoSInitialization(rmw_qos_history_policy_t history_policy_arg, size_t depth_arg, bool print_depth_warning = true);
  static QoSInitialization from_rmw(const rmw_qos_profile_t & rmw_qos);
};
struct KeepAll : public rclcpp::QoSInitialization
{
  KeepAll();
};
struct KeepLast : public rclcpp::QoSInitialization
{
  explicit KeepLast(size_t depth, bool print_depth_warning = true);
};

class QoS
{
public:
  explicit QoS(
    const QoSInitialization & qos_initialization,
    const rmw_qos_profile_t & initial_profile = rmw_qos_profile_default);
  QoS(size_t history_depth);  // NOLINT(runtime/explicit): conversion constructor
  rmw_qos_profile_t & get_rmw_qos_profile();
  const rmw_qos_profile_t & get_rmw_qos_profile() const;
  QoS & history(HistoryPolicy history);
  QoS & history(rmw_qos_history_policy_t history);
  QoS & keep_last(size_t depth);
  QoS & keep_all();
  QoS & reliability(rmw_qos_reliability_policy_t reliability);
  QoS & reliability(ReliabilityPolicy reliability);
  QoS & reliable();
  QoS & best_effort();
  QoS & reliability_best_available();
  QoS & durability(rmw_qos_durability_policy_t durability);
  QoS & durability(DurabilityPolicy durability);
  QoS & durability_volatile();
  QoS & transient_local();
  QoS & durability_best_available();
  QoS & deadline(rmw_time_t deadline);
  QoS & deadline(const rclcpp::Duration & deadline);
  QoS & lifespan(rmw_time_t lifespan);
  QoS & lifespan(const rclcpp::Duration & lifespan);
  QoS & liveliness(rmw_qos_liveliness_policy_t liveliness);
  QoS & liveliness(LivelinessPolicy liveliness);
  QoS & liveliness_lease_duration(rmw_time_t liveliness_lease_duration);
  QoS & liveliness_lease_duration(const rclcpp::Duration & liveliness_lease_duration);
  QoS & avoid_ros_namespace_conventions(bool avoid_ros_namespace_conventions);
  HistoryPolicy history() const;
  size_t depth() const;
  ReliabilityPolicy reliability() const;
  DurabilityPolicy durability() const;
  rclcpp::Duration deadline() const;
  rclcpp::Duration lifespan() const;
  LivelinessPolicy liveliness() const;
  rclcpp::Duration liveliness_lease_duration() const;
  bool avoid_ros_namespace_conventions() const;
};
bool operator==(const QoS & left, const QoS & right);
bool operator!=(const QoS & left, const QoS & right);

class ClockQoS : public QoS
{
public:
  explicit ClockQoS(const QoSInitialization & qos_initialization = KeepLast(1));
};
class SensorDataQoS : public QoS
{
public:
  explicit SensorDataQoS(
    const QoSInitialization & qos_initialization = (QoSInitialization::from_rmw(rmw_qos_profile_sensor_data)));
};
class ParametersQoS : public QoS
{
public:
  explicit ParametersQoS(
    const QoSInitialization & qos_initialization = (QoSInitialization::from_rmw(rmw_qos_profile_parameters)));
};
class ServicesQoS : public QoS
{
public:
  explicit ServicesQoS(
    const QoSInitialization & qos_initialization = (QoSInitialization::from_rmw(rmw_qos_profile_services_default)));
};
class ParameterEventsQoS : public QoS
{
public:
  explicit ParameterEventsQoS(
    const QoSInitialization & qos_initialization = (QoSInitialization::from_rmw(rmw_qos_profile_parameter_events)));
};
class RosoutQoS : public QoS
{
public:
  explicit RosoutQoS(
    const QoSInitialization & rosout_qos_initialization = (QoSInitialization::from_rmw(rcl_qos_profile_rosout_default)));
};
class SystemDefaultsQoS : public QoS
{
public:
  explicit SystemDefaultsQoS(
    const QoSInitialization & qos_initialization = (QoSInitialization::from_rmw(rmw_qos_profile_system_default)));
};
class BestAvailableQoS : public QoS
{
public:
  explicit BestAvailableQoS(
    const QoSInitialization & qos_initialization = (QoSInitialization::from_rmw(rmw_qos_profile_best_available)));
};

// ---- parameters -----------------------------------------------------------------------------
enum ParameterType : uint8_t
{
  PARAMETER_NOT_SET = 0,
  PARAMETER_BOOL = 1,
  PARAMETER_INTEGER = 2,
  PARAMETER_DOUBLE = 3,
  PARAMETER_STRING = 4,
  PARAMETER_BYTE_ARRAY = 5,
  PARAMETER_BOOL_ARRAY = 6,
  PARAMETER_INTEGER_ARRAY = 7,
  PARAMETER_DOUBLE_ARRAY = 8,
  PARAMETER_STRING_ARRAY = 9,
};
std::string to_string(ParameterType type);

namespace archlog_detail
{
// what ParameterValue::get<T>() returns: a std::string for anything convertible to one
template<typename T, typename = void>
struct parameter_type
{
  using type = T;
};
template<typename T>
struct parameter_type<T, typename std::enable_if<std::is_convertible<T, std::string>::value>::type>
{
  using type = std::string;
};
}  // namespace archlog_detail

class ParameterValue
{
public:
  ParameterValue();
  explicit ParameterValue(const bool bool_value);
  explicit ParameterValue(const int int_value);
  explicit ParameterValue(const int64_t int_value);
  explicit ParameterValue(const float double_value);
  explicit ParameterValue(const double double_value);
  explicit ParameterValue(const std::string & string_value);
  explicit ParameterValue(const char * string_value);
  explicit ParameterValue(const std::vector<uint8_t> & byte_array_value);
  explicit ParameterValue(const std::vector<bool> & bool_array_value);
  explicit ParameterValue(const std::vector<int> & int_array_value);
  explicit ParameterValue(const std::vector<int64_t> & int_array_value);
  explicit ParameterValue(const std::vector<float> & double_array_value);
  explicit ParameterValue(const std::vector<double> & double_array_value);
  explicit ParameterValue(const std::vector<std::string> & string_array_value);
  ParameterType get_type() const;
  template<typename T>
  typename archlog_detail::parameter_type<T>::type get() const;
};
std::string to_string(const ParameterValue & type);

class Parameter
{
public:
  Parameter();
  explicit Parameter(const std::string & name);
  Parameter(const std::string & name, const ParameterValue & value);
  template<typename ValueTypeT>
  Parameter(const std::string & name, ValueTypeT value);
  bool operator==(const Parameter & rhs) const;
  bool operator!=(const Parameter & rhs) const;
  ParameterType get_type() const;
  std::string get_type_name() const;
  const std::string & get_name() const;
  const ParameterValue & get_parameter_value() const;
  template<typename T>
  typename archlog_detail::parameter_type<T>::type get_value() const;
  bool as_bool() const;
  int64_t as_int() const;
  double as_double() const;
  const std::string & as_string() const;
  const std::vector<uint8_t> & as_byte_array() const;
  const std::vector<bool> & as_bool_array() const;
  const std::vector<int64_t> & as_integer_array() const;
  const std::vector<double> & as_double_array() const;
  const std::vector<std::string> & as_string_array() const;
  std::string value_to_string() const;
};

namespace exceptions
{
class InvalidParametersException : public std::runtime_error
{
  using std::runtime_error::runtime_error;
};
class InvalidParameterValueException : public std::runtime_error
{
  using std::runtime_error::runtime_error;
};
class InvalidParameterTypeException : public std::runtime_error
{
public:
  InvalidParameterTypeException(const std::string & name, const std::string message);
};
class ParameterAlreadyDeclaredException : public std::runtime_error
{
  using std::runtime_error::runtime_error;
};
class ParameterNotDeclaredException : public std::runtime_error
{
  using std::runtime_error::runtime_error;
};
class ParameterImmutableException : public std::runtime_error
{
  using std::runtime_error::runtime_error;
};
class ParameterUninitializedException : public std::runtime_error
{
  using std::runtime_error::runtime_error;
};
class RCLError : public std::runtime_error
{
  using std::runtime_error::runtime_error;
};
}  // namespace exceptions

// ---- entities ---------------------------------------------------------------------------------
enum class CallbackGroupType { MutuallyExclusive, Reentrant };
class CallbackGroup
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(CallbackGroup)
  CallbackGroupType type() const;
};

class TimerBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(TimerBase)
  virtual ~TimerBase();
  void cancel();
  bool is_canceled();
  void reset();
  bool is_ready();
  std::chrono::nanoseconds time_until_trigger();
};
template<typename FunctorT>
class GenericTimer : public TimerBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(GenericTimer)
};
template<typename FunctorT>
class WallTimer : public GenericTimer<FunctorT>
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(WallTimer)
};

class QOSEventHandlerBase
{
};
struct QOSDeadlineOfferedInfo
{
  int32_t total_count;
  int32_t total_count_change;
};
struct QOSDeadlineRequestedInfo
{
  int32_t total_count;
  int32_t total_count_change;
};
struct QOSLivelinessChangedInfo
{
  int32_t alive_count;
  int32_t not_alive_count;
  int32_t alive_count_change;
  int32_t not_alive_count_change;
};
struct QOSLivelinessLostInfo
{
  int32_t total_count;
  int32_t total_count_change;
};
struct MatchedInfo
{
  size_t total_count;
  size_t total_count_change;
  size_t current_count;
  int32_t current_count_change;
};
struct QOSOfferedIncompatibleQoSInfo
{
  int32_t total_count;
  int32_t total_count_change;
  int last_policy_kind;
};
using QOSRequestedIncompatibleQoSInfo = QOSOfferedIncompatibleQoSInfo;
using QOSDeadlineOfferedCallbackType = std::function<void (QOSDeadlineOfferedInfo &)>;
using QOSDeadlineRequestedCallbackType = std::function<void (QOSDeadlineRequestedInfo &)>;
using QOSLivelinessChangedCallbackType = std::function<void (QOSLivelinessChangedInfo &)>;
using QOSLivelinessLostCallbackType = std::function<void (QOSLivelinessLostInfo &)>;
using QOSOfferedIncompatibleQoSCallbackType = std::function<void (QOSOfferedIncompatibleQoSInfo &)>;
using QOSRequestedIncompatibleQoSCallbackType = std::function<void (QOSRequestedIncompatibleQoSInfo &)>;
struct QOSMessageLostInfo
{
  size_t total_count;
  size_t total_count_change;
};
using QOSMessageLostCallbackType = std::function<void (QOSMessageLostInfo &)>;
struct IncompatibleTypeInfo
{
  int32_t total_count;
  int32_t total_count_change;
};
using IncompatibleTypeCallbackType = std::function<void (IncompatibleTypeInfo &)>;
using PublisherMatchedCallbackType = std::function<void (MatchedInfo &)>;
using SubscriptionMatchedCallbackType = std::function<void (MatchedInfo &)>;
struct PublisherEventCallbacks
{
  std::function<void (QOSDeadlineOfferedInfo &)> deadline_callback;
  std::function<void (QOSLivelinessLostInfo &)> liveliness_callback;
  std::function<void (QOSOfferedIncompatibleQoSInfo &)> incompatible_qos_callback;
  std::function<void (MatchedInfo &)> matched_callback;
  IncompatibleTypeCallbackType incompatible_type_callback;
};
struct SubscriptionEventCallbacks
{
  std::function<void (QOSDeadlineRequestedInfo &)> deadline_callback;
  std::function<void (QOSLivelinessChangedInfo &)> liveliness_callback;
  std::function<void (QOSRequestedIncompatibleQoSInfo &)> incompatible_qos_callback;
  std::function<void (MatchedInfo &)> matched_callback;
  QOSMessageLostCallbackType message_lost_callback;
  IncompatibleTypeCallbackType incompatible_type_callback;
};
enum class QosPolicyKind { AvoidRosNamespaceConventions, Deadline, Depth, Durability, History, Lifespan, Liveliness,
  LivelinessLeaseDuration, Reliability };
class QosOverridingOptions
{
public:
  QosOverridingOptions();
  QosOverridingOptions(std::initializer_list<QosPolicyKind> policy_kinds, std::string id = {});  // NOLINT
  static QosOverridingOptions with_default_policies(std::string id = {});
};
enum class IntraProcessSetting { Enable, Disable, NodeDefault };

struct PublisherOptionsBase
{
  IntraProcessSetting use_intra_process_comm = IntraProcessSetting::NodeDefault;
  PublisherEventCallbacks event_callbacks;
  bool use_default_callbacks = true;
  std::shared_ptr<rclcpp::CallbackGroup> callback_group;
  QosOverridingOptions qos_overriding_options;
};
template<typename Allocator>
struct PublisherOptionsWithAllocator : public PublisherOptionsBase
{
  std::shared_ptr<Allocator> allocator = nullptr;
  PublisherOptionsWithAllocator();
};
using PublisherOptions = PublisherOptionsWithAllocator<std::allocator<void>>;

struct SubscriptionOptionsBase
{
  SubscriptionEventCallbacks event_callbacks;
  bool use_default_callbacks = true;
  bool ignore_local_publications = false;
  std::shared_ptr<rclcpp::CallbackGroup> callback_group = nullptr;
  IntraProcessSetting use_intra_process_comm = IntraProcessSetting::NodeDefault;
  QosOverridingOptions qos_overriding_options;
};
template<typename Allocator>
struct SubscriptionOptionsWithAllocator : public SubscriptionOptionsBase
{
  std::shared_ptr<Allocator> allocator = nullptr;
  SubscriptionOptionsWithAllocator();
};
using SubscriptionOptions = SubscriptionOptionsWithAllocator<std::allocator<void>>;

class SerializedMessage
{
public:
  SerializedMessage();
  size_t size() const;
};
class MessageInfo
{
};

class PublisherBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(PublisherBase)
  virtual ~PublisherBase();
  const char * get_topic_name() const;
  size_t get_subscription_count() const;
  size_t get_intra_process_subscription_count() const;
  rclcpp::QoS get_actual_qos() const;
  bool assert_liveliness() const;
};
template<typename MessageT, typename AllocatorT = std::allocator<void>>
class Publisher : public PublisherBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Publisher<MessageT, AllocatorT>)
  using ROSMessageType = MessageT;
  virtual void publish(std::unique_ptr<MessageT> msg);
  virtual void publish(const MessageT & msg);
  void publish(const rclcpp::SerializedMessage & serialized_msg);
  bool can_loan_messages() const;
};
class GenericPublisher : public PublisherBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(GenericPublisher)
  void publish(const rclcpp::SerializedMessage & message);
};

class SubscriptionBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(SubscriptionBase)
  virtual ~SubscriptionBase();
  const char * get_topic_name() const;
  size_t get_publisher_count() const;
  rclcpp::QoS get_actual_qos() const;
};
template<typename MessageT, typename AllocatorT = std::allocator<void>>
class Subscription : public SubscriptionBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Subscription)
  using ROSMessageType = MessageT;
};
class GenericSubscription : public SubscriptionBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(GenericSubscription)
};

class ServiceBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(ServiceBase)
  virtual ~ServiceBase();
  const char * get_service_name();
};
template<typename ServiceT>
class Service : public ServiceBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Service)
  void send_response(rmw_request_id_t & req_id, typename ServiceT::Response & response);
};

enum class FutureReturnCode { SUCCESS, INTERRUPTED, TIMEOUT };

class ClientBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(ClientBase)
  virtual ~ClientBase();
  const char * get_service_name() const;
  bool service_is_ready() const;
  template<typename RepT = int64_t, typename RatioT = std::milli>
  bool wait_for_service(std::chrono::duration<RepT, RatioT> timeout = std::chrono::duration<RepT, RatioT>(-1));
};
template<typename ServiceT>
class Client : public ClientBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Client)
  using SharedRequest = typename ServiceT::Request::SharedPtr;
  using SharedResponse = typename ServiceT::Response::SharedPtr;
  using Promise = std::promise<SharedResponse>;
  using SharedPromise = std::shared_ptr<Promise>;
  using Future = std::future<SharedResponse>;
  using SharedFuture = std::shared_future<SharedResponse>;
  using CallbackType = std::function<void (SharedFuture)>;
  struct FutureAndRequestId
  {
    Future future;
    int64_t request_id;
    SharedResponse get();
    bool valid() const noexcept;
    void wait() const;
    template<class Rep, class Period>
    std::future_status wait_for(const std::chrono::duration<Rep, Period> & timeout_duration) const;
    SharedFuture share() noexcept;
  };
  struct SharedFutureAndRequestId
  {
    SharedFuture future;
    int64_t request_id;
    SharedResponse get() const;
    bool valid() const noexcept;
    void wait() const;
    template<class Rep, class Period>
    std::future_status wait_for(const std::chrono::duration<Rep, Period> & timeout_duration) const;
  };
  FutureAndRequestId async_send_request(SharedRequest request);
  template<typename CallbackT>
  SharedFutureAndRequestId async_send_request(SharedRequest request, CallbackT && cb);
  bool remove_pending_request(int64_t request_id);
  size_t prune_pending_requests();
};

// ---- nodes ------------------------------------------------------------------------------------
namespace node_interfaces
{
class NodeBaseInterface
{
public:
  RCLCPP_SMART_PTR_ALIASES_ONLY(NodeBaseInterface)
  virtual ~NodeBaseInterface();
  virtual const char * get_name() const = 0;
  virtual const char * get_namespace() const = 0;
  virtual const char * get_fully_qualified_name() const = 0;
  virtual rclcpp::CallbackGroup::SharedPtr get_default_callback_group() = 0;
  virtual rclcpp::CallbackGroup::SharedPtr create_callback_group(
    rclcpp::CallbackGroupType group_type, bool automatically_add_to_executor_with_node = true) = 0;
  virtual bool get_use_intra_process_default() const = 0;
  virtual rclcpp::Context::SharedPtr get_context() = 0;
};
#define ARCHLOG_NODE_INTERFACE(Name) \
  class Name \
  { \
public: \
    RCLCPP_SMART_PTR_ALIASES_ONLY(Name) \
    virtual ~Name(); \
  };
class NodeClockInterface
{
public:
  RCLCPP_SMART_PTR_ALIASES_ONLY(NodeClockInterface)
  virtual ~NodeClockInterface();
  virtual rclcpp::Clock::SharedPtr get_clock() = 0;
};
ARCHLOG_NODE_INTERFACE(NodeGraphInterface)
ARCHLOG_NODE_INTERFACE(NodeLoggingInterface)
ARCHLOG_NODE_INTERFACE(NodeServicesInterface)
ARCHLOG_NODE_INTERFACE(NodeTimeSourceInterface)
ARCHLOG_NODE_INTERFACE(NodeTimersInterface)
ARCHLOG_NODE_INTERFACE(NodeTopicsInterface)
ARCHLOG_NODE_INTERFACE(NodeWaitablesInterface)
ARCHLOG_NODE_INTERFACE(NodeTypeDescriptionsInterface)
#undef ARCHLOG_NODE_INTERFACE
class NodeParametersInterface
{
public:
  RCLCPP_SMART_PTR_ALIASES_ONLY(NodeParametersInterface)
  virtual ~NodeParametersInterface();
  virtual bool has_parameter(const std::string & name) const = 0;
  virtual const rclcpp::ParameterValue & declare_parameter(
    const std::string & name, const rclcpp::ParameterValue & default_value,
    const rcl_interfaces::msg::ParameterDescriptor & parameter_descriptor =
    rcl_interfaces::msg::ParameterDescriptor(),
    bool ignore_override = false) = 0;
  virtual const rclcpp::ParameterValue & declare_parameter(
    const std::string & name, rclcpp::ParameterType type,
    const rcl_interfaces::msg::ParameterDescriptor & parameter_descriptor =
    rcl_interfaces::msg::ParameterDescriptor(),
    bool ignore_override = false) = 0;
  virtual void undeclare_parameter(const std::string & name) = 0;
  virtual std::vector<rclcpp::Parameter> get_parameters(const std::vector<std::string> & names) const = 0;
  virtual rclcpp::Parameter get_parameter(const std::string & name) const = 0;
  virtual bool get_parameter(const std::string & name, rclcpp::Parameter & parameter) const = 0;
  virtual std::vector<rcl_interfaces::msg::SetParametersResult> set_parameters(
    const std::vector<rclcpp::Parameter> & parameters) = 0;
  virtual const std::map<std::string, rclcpp::ParameterValue> & get_parameter_overrides() const = 0;
};
struct OnSetParametersCallbackHandle
{
  RCLCPP_SMART_PTR_DEFINITIONS(OnSetParametersCallbackHandle)
  using OnSetParametersCallbackType =
    std::function<rcl_interfaces::msg::SetParametersResult(const std::vector<rclcpp::Parameter> &)>;
  using OnParametersSetCallbackType = OnSetParametersCallbackType;
  OnSetParametersCallbackType callback;
};
struct PreSetParametersCallbackHandle
{
  RCLCPP_SMART_PTR_DEFINITIONS(PreSetParametersCallbackHandle)
  using PreSetParametersCallbackType = std::function<void (std::vector<rclcpp::Parameter> &)>;
};
struct PostSetParametersCallbackHandle
{
  RCLCPP_SMART_PTR_DEFINITIONS(PostSetParametersCallbackHandle)
  using PostSetParametersCallbackType = std::function<void (const std::vector<rclcpp::Parameter> &)>;
};
}  // namespace node_interfaces

class NodeOptions
{
public:
  explicit NodeOptions();
  NodeOptions(const NodeOptions & other);
  NodeOptions & operator=(const NodeOptions & other);
  rclcpp::Context::SharedPtr context() const;
  NodeOptions & context(rclcpp::Context::SharedPtr context);
  const std::vector<std::string> & arguments() const;
  NodeOptions & arguments(const std::vector<std::string> & arguments);
  std::vector<rclcpp::Parameter> & parameter_overrides();
  const std::vector<rclcpp::Parameter> & parameter_overrides() const;
  NodeOptions & parameter_overrides(const std::vector<rclcpp::Parameter> & parameter_overrides);
  template<typename ParameterT>
  NodeOptions & append_parameter_override(const std::string & name, const ParameterT & value);
  bool use_global_arguments() const;
  NodeOptions & use_global_arguments(bool use_global_arguments);
  bool enable_rosout() const;
  NodeOptions & enable_rosout(bool enable_rosout);
  bool use_intra_process_comms() const;
  NodeOptions & use_intra_process_comms(bool use_intra_process_comms);
  bool enable_topic_statistics() const;
  NodeOptions & enable_topic_statistics(bool enable_topic_statistics);
  bool start_parameter_services() const;
  NodeOptions & start_parameter_services(bool start_parameter_services);
  bool start_parameter_event_publisher() const;
  NodeOptions & start_parameter_event_publisher(bool start_parameter_event_publisher);
  bool use_clock_thread() const;
  NodeOptions & use_clock_thread(bool use_clock_thread);
  bool allow_undeclared_parameters() const;
  NodeOptions & allow_undeclared_parameters(bool allow_undeclared_parameters);
  bool automatically_declare_parameters_from_overrides() const;
  NodeOptions & automatically_declare_parameters_from_overrides(bool automatically_declare_parameters_from_overrides);
  bool enable_logger_service() const;
  NodeOptions & enable_logger_service(bool enable_log_service);
};

class Node : public std::enable_shared_from_this<Node>
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Node)
  using OnSetParametersCallbackHandle = rclcpp::node_interfaces::OnSetParametersCallbackHandle;
  using OnParametersSetCallbackType = OnSetParametersCallbackHandle::OnParametersSetCallbackType;
  using PreSetParametersCallbackHandle = rclcpp::node_interfaces::PreSetParametersCallbackHandle;
  using PostSetParametersCallbackHandle = rclcpp::node_interfaces::PostSetParametersCallbackHandle;

  explicit Node(const std::string & node_name, const NodeOptions & options = NodeOptions());
  explicit Node(
    const std::string & node_name, const std::string & namespace_, const NodeOptions & options = NodeOptions());
  virtual ~Node();

  const char * get_name() const;
  const char * get_namespace() const;
  const char * get_fully_qualified_name() const;
  rclcpp::Logger get_logger() const;
  rclcpp::CallbackGroup::SharedPtr create_callback_group(
    rclcpp::CallbackGroupType group_type, bool automatically_add_to_executor_with_node = true);

  template<typename MessageT, typename AllocatorT = std::allocator<void>,
    typename PublisherT = rclcpp::Publisher<MessageT, AllocatorT>>
  std::shared_ptr<PublisherT> create_publisher(
    const std::string & topic_name, const rclcpp::QoS & qos,
    const PublisherOptionsWithAllocator<AllocatorT> & options = PublisherOptionsWithAllocator<AllocatorT>());

  template<typename MessageT, typename CallbackT, typename AllocatorT = std::allocator<void>,
    typename SubscriptionT = rclcpp::Subscription<MessageT, AllocatorT>>
  std::shared_ptr<SubscriptionT> create_subscription(
    const std::string & topic_name, const rclcpp::QoS & qos, CallbackT && callback,
    const SubscriptionOptionsWithAllocator<AllocatorT> & options = SubscriptionOptionsWithAllocator<AllocatorT>());

  template<typename DurationRepT = int64_t, typename DurationT = std::milli, typename CallbackT>
  typename rclcpp::WallTimer<CallbackT>::SharedPtr create_wall_timer(
    std::chrono::duration<DurationRepT, DurationT> period, CallbackT callback,
    rclcpp::CallbackGroup::SharedPtr group = nullptr, bool autostart = true);

  template<typename DurationRepT = int64_t, typename DurationT = std::milli, typename CallbackT>
  typename rclcpp::GenericTimer<CallbackT>::SharedPtr create_timer(
    std::chrono::duration<DurationRepT, DurationT> period, CallbackT callback,
    rclcpp::CallbackGroup::SharedPtr group = nullptr);

  template<typename ServiceT>
  typename rclcpp::Client<ServiceT>::SharedPtr create_client(
    const std::string & service_name, const rmw_qos_profile_t & qos_profile = rmw_qos_profile_services_default,
    rclcpp::CallbackGroup::SharedPtr group = nullptr);
  template<typename ServiceT>
  typename rclcpp::Client<ServiceT>::SharedPtr create_client(
    const std::string & service_name, const rclcpp::QoS & qos, rclcpp::CallbackGroup::SharedPtr group = nullptr);

  template<typename ServiceT, typename CallbackT>
  typename rclcpp::Service<ServiceT>::SharedPtr create_service(
    const std::string & service_name, CallbackT && callback,
    const rmw_qos_profile_t & qos_profile = rmw_qos_profile_services_default,
    rclcpp::CallbackGroup::SharedPtr group = nullptr);
  template<typename ServiceT, typename CallbackT>
  typename rclcpp::Service<ServiceT>::SharedPtr create_service(
    const std::string & service_name, CallbackT && callback, const rclcpp::QoS & qos,
    rclcpp::CallbackGroup::SharedPtr group = nullptr);

  std::shared_ptr<rclcpp::GenericPublisher> create_generic_publisher(
    const std::string & topic_name, const std::string & topic_type, const rclcpp::QoS & qos,
    const rclcpp::PublisherOptions & options = rclcpp::PublisherOptions());
  std::shared_ptr<rclcpp::GenericSubscription> create_generic_subscription(
    const std::string & topic_name, const std::string & topic_type, const rclcpp::QoS & qos,
    std::function<void(std::shared_ptr<rclcpp::SerializedMessage>)> callback,
    const rclcpp::SubscriptionOptions & options = rclcpp::SubscriptionOptions());

  const rclcpp::ParameterValue & declare_parameter(
    const std::string & name, const rclcpp::ParameterValue & default_value,
    const rcl_interfaces::msg::ParameterDescriptor & parameter_descriptor =
    rcl_interfaces::msg::ParameterDescriptor(),
    bool ignore_override = false);
  const rclcpp::ParameterValue & declare_parameter(
    const std::string & name, rclcpp::ParameterType type,
    const rcl_interfaces::msg::ParameterDescriptor & parameter_descriptor =
    rcl_interfaces::msg::ParameterDescriptor{},
    bool ignore_override = false);
  template<typename ParameterT>
  auto declare_parameter(
    const std::string & name, const ParameterT & default_value,
    const rcl_interfaces::msg::ParameterDescriptor & parameter_descriptor =
    rcl_interfaces::msg::ParameterDescriptor(),
    bool ignore_override = false) -> typename rclcpp::archlog_detail::parameter_type<ParameterT>::type;
  template<typename ParameterT>
  auto declare_parameter(
    const std::string & name,
    const rcl_interfaces::msg::ParameterDescriptor & parameter_descriptor =
    rcl_interfaces::msg::ParameterDescriptor(),
    bool ignore_override = false) -> typename rclcpp::archlog_detail::parameter_type<ParameterT>::type;
  template<typename ParameterT>
  std::vector<ParameterT> declare_parameters(
    const std::string & namespace_, const std::map<std::string, ParameterT> & parameters,
    bool ignore_overrides = false);
  template<typename ParameterT>
  std::vector<ParameterT> declare_parameters(
    const std::string & namespace_,
    const std::map<std::string, std::pair<ParameterT, rcl_interfaces::msg::ParameterDescriptor>> & parameters,
    bool ignore_overrides = false);
  void undeclare_parameter(const std::string & name);
  bool has_parameter(const std::string & name) const;
  rcl_interfaces::msg::SetParametersResult set_parameter(const rclcpp::Parameter & parameter);
  std::vector<rcl_interfaces::msg::SetParametersResult> set_parameters(
    const std::vector<rclcpp::Parameter> & parameters);
  rcl_interfaces::msg::SetParametersResult set_parameters_atomically(
    const std::vector<rclcpp::Parameter> & parameters);
  rclcpp::Parameter get_parameter(const std::string & name) const;
  bool get_parameter(const std::string & name, rclcpp::Parameter & parameter) const;
  template<typename ParameterT>
  bool get_parameter(const std::string & name, ParameterT & parameter) const;
  template<typename ParameterT>
  bool get_parameter_or(
    const std::string & name, ParameterT & parameter, const ParameterT & alternative_value) const;
  template<typename ParameterT>
  ParameterT get_parameter_or(const std::string & name, const ParameterT & alternative_value) const;
  std::vector<rclcpp::Parameter> get_parameters(const std::vector<std::string> & names) const;
  template<typename ParameterT>
  bool get_parameters(const std::string & prefix, std::map<std::string, ParameterT> & values) const;
  rcl_interfaces::msg::ParameterDescriptor describe_parameter(const std::string & name) const;
  rcl_interfaces::msg::ListParametersResult list_parameters(
    const std::vector<std::string> & prefixes, uint64_t depth) const;
  OnSetParametersCallbackHandle::SharedPtr add_on_set_parameters_callback(OnParametersSetCallbackType callback);
  void remove_on_set_parameters_callback(const OnSetParametersCallbackHandle * const handler);
  PreSetParametersCallbackHandle::SharedPtr add_pre_set_parameters_callback(
    PreSetParametersCallbackHandle::PreSetParametersCallbackType callback);
  PostSetParametersCallbackHandle::SharedPtr add_post_set_parameters_callback(
    PostSetParametersCallbackHandle::PostSetParametersCallbackType callback);
  void remove_pre_set_parameters_callback(const PreSetParametersCallbackHandle * const handler);
  void remove_post_set_parameters_callback(const PostSetParametersCallbackHandle * const handler);

  std::vector<std::string> get_node_names() const;
  std::map<std::string, std::vector<std::string>> get_topic_names_and_types() const;
  std::map<std::string, std::vector<std::string>> get_service_names_and_types() const;
  size_t count_publishers(const std::string & topic_name) const;
  size_t count_subscribers(const std::string & topic_name) const;
  rclcpp::Clock::SharedPtr get_clock();
  rclcpp::Clock::ConstSharedPtr get_clock() const;
  rclcpp::Time now() const;
  bool assert_liveliness() const;

  rclcpp::node_interfaces::NodeBaseInterface::SharedPtr get_node_base_interface();
  rclcpp::node_interfaces::NodeClockInterface::SharedPtr get_node_clock_interface();
  rclcpp::node_interfaces::NodeGraphInterface::SharedPtr get_node_graph_interface();
  rclcpp::node_interfaces::NodeLoggingInterface::SharedPtr get_node_logging_interface();
  rclcpp::node_interfaces::NodeTimersInterface::SharedPtr get_node_timers_interface();
  rclcpp::node_interfaces::NodeTopicsInterface::SharedPtr get_node_topics_interface();
  rclcpp::node_interfaces::NodeServicesInterface::SharedPtr get_node_services_interface();
  rclcpp::node_interfaces::NodeWaitablesInterface::SharedPtr get_node_waitables_interface();
  rclcpp::node_interfaces::NodeParametersInterface::SharedPtr get_node_parameters_interface();
  rclcpp::node_interfaces::NodeTimeSourceInterface::SharedPtr get_node_time_source_interface();
  const std::string & get_sub_namespace() const;
  const std::string & get_effective_namespace() const;
  rclcpp::Node::SharedPtr create_sub_node(const std::string & sub_namespace);
  const rclcpp::NodeOptions & get_node_options() const;

protected:
  Node(const Node & other, const std::string & sub_namespace);
};

// ---- free functions to create entities (rclcpp/create_*.hpp) ---------------------------------------
template<typename MessageT, typename AllocatorT = std::allocator<void>,
  typename PublisherT = rclcpp::Publisher<MessageT, AllocatorT>, typename NodeT>
std::shared_ptr<PublisherT> create_publisher(
  NodeT && node, const std::string & topic_name, const rclcpp::QoS & qos,
  const rclcpp::PublisherOptionsWithAllocator<AllocatorT> & options =
  rclcpp::PublisherOptionsWithAllocator<AllocatorT>());

template<typename MessageT, typename CallbackT, typename AllocatorT = std::allocator<void>,
  typename SubscriptionT = rclcpp::Subscription<MessageT, AllocatorT>, typename NodeT>
std::shared_ptr<SubscriptionT> create_subscription(
  NodeT && node, const std::string & topic_name, const rclcpp::QoS & qos, CallbackT && callback,
  const rclcpp::SubscriptionOptionsWithAllocator<AllocatorT> & options =
  rclcpp::SubscriptionOptionsWithAllocator<AllocatorT>());

template<typename CallbackT>
typename rclcpp::GenericTimer<CallbackT>::SharedPtr create_timer(
  node_interfaces::NodeBaseInterface::SharedPtr node_base,
  node_interfaces::NodeTimersInterface::SharedPtr node_timers, rclcpp::Clock::SharedPtr clock,
  rclcpp::Duration period, CallbackT && callback, rclcpp::CallbackGroup::SharedPtr group = nullptr);
template<typename NodeT, typename CallbackT>
typename rclcpp::GenericTimer<CallbackT>::SharedPtr create_timer(
  NodeT node, rclcpp::Clock::SharedPtr clock, rclcpp::Duration period, CallbackT && callback,
  rclcpp::CallbackGroup::SharedPtr group = nullptr);
template<typename DurationRepT, typename DurationT, typename CallbackT>
typename rclcpp::GenericTimer<CallbackT>::SharedPtr create_timer(
  rclcpp::Clock::SharedPtr clock, std::chrono::duration<DurationRepT, DurationT> period, CallbackT callback,
  rclcpp::CallbackGroup::SharedPtr group, node_interfaces::NodeBaseInterface * node_base,
  node_interfaces::NodeTimersInterface * node_timers, bool autostart = true);
template<typename DurationRepT, typename DurationT, typename CallbackT>
typename rclcpp::WallTimer<CallbackT>::SharedPtr create_wall_timer(
  std::chrono::duration<DurationRepT, DurationT> period, CallbackT callback, rclcpp::CallbackGroup::SharedPtr group,
  node_interfaces::NodeBaseInterface * node_base, node_interfaces::NodeTimersInterface * node_timers);

template<typename ServiceT, typename CallbackT>
typename rclcpp::Service<ServiceT>::SharedPtr create_service(
  std::shared_ptr<node_interfaces::NodeBaseInterface> node_base,
  std::shared_ptr<node_interfaces::NodeServicesInterface> node_services, const std::string & service_name,
  CallbackT && callback, const rclcpp::QoS & qos, rclcpp::CallbackGroup::SharedPtr group);
template<typename ServiceT>
typename rclcpp::Client<ServiceT>::SharedPtr create_client(
  std::shared_ptr<node_interfaces::NodeBaseInterface> node_base,
  std::shared_ptr<node_interfaces::NodeGraphInterface> node_graph,
  std::shared_ptr<node_interfaces::NodeServicesInterface> node_services, const std::string & service_name,
  const rclcpp::QoS & qos = rclcpp::ServicesQoS(), rclcpp::CallbackGroup::SharedPtr group = nullptr);

class TimeSource
{
public:
  template<typename NodeT>
  explicit TimeSource(NodeT node, const rclcpp::QoS & qos = rclcpp::ClockQoS(), bool use_clock_thread = true);
  TimeSource();
  void attachNode(rclcpp::Node::SharedPtr node);
  void attachClock(rclcpp::Clock::SharedPtr clock);
  void detachClock(rclcpp::Clock::SharedPtr clock);
};

// ---- parameter helpers --------------------------------------------------------------------------
class ParameterEventHandler
{
public:
  template<typename NodeT>
  explicit ParameterEventHandler(NodeT node, const rclcpp::QoS & qos = rclcpp::ParameterEventsQoS());
  using ParameterCallbackType = std::function<void (const rclcpp::Parameter &)>;
  struct ParameterCallbackHandle
  {
    RCLCPP_SMART_PTR_DEFINITIONS(ParameterCallbackHandle)
  };
  ParameterCallbackHandle::SharedPtr add_parameter_callback(
    const std::string & parameter_name, ParameterCallbackType callback, const std::string & node_name = "");
};

// ---- executors and the process ------------------------------------------------------------------
class InitOptions
{
public:
  InitOptions();
  InitOptions & auto_initialize_logging(bool initialize_logging);
};
enum class SignalHandlerOptions { All, SigInt, SigTerm, None };
void init(
  int argc, char const * const * argv, const InitOptions & init_options = InitOptions(),
  SignalHandlerOptions signal_handler_options = SignalHandlerOptions::All);
std::vector<std::string> init_and_remove_ros_arguments(
  int argc, char const * const * argv, const InitOptions & init_options = InitOptions());
std::vector<std::string> remove_ros_arguments(int argc, char const * const * argv);
bool ok(rclcpp::Context::SharedPtr context = nullptr);
bool shutdown(rclcpp::Context::SharedPtr context = nullptr, const std::string & reason = "user called rclcpp::shutdown()");
void on_shutdown(std::function<void()> callback, rclcpp::Context::SharedPtr context = nullptr);

struct ExecutorOptions
{
  ExecutorOptions();
  rclcpp::Context::SharedPtr context;
};
class Executor
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Executor)
  explicit Executor(const rclcpp::ExecutorOptions & options = rclcpp::ExecutorOptions());
  virtual ~Executor();
  virtual void spin();
  virtual void add_node(rclcpp::node_interfaces::NodeBaseInterface::SharedPtr node_ptr, bool notify = true);
  virtual void add_node(std::shared_ptr<rclcpp::Node> node_ptr, bool notify = true);
  virtual void remove_node(rclcpp::node_interfaces::NodeBaseInterface::SharedPtr node_ptr, bool notify = true);
  virtual void remove_node(std::shared_ptr<rclcpp::Node> node_ptr, bool notify = true);
  virtual void add_callback_group(
    rclcpp::CallbackGroup::SharedPtr group_ptr,
    rclcpp::node_interfaces::NodeBaseInterface::SharedPtr node_ptr, bool notify = true);
  template<typename RepT = int64_t, typename T = std::milli>
  void spin_node_once(
    std::shared_ptr<rclcpp::Node> node, std::chrono::duration<RepT, T> timeout = std::chrono::duration<RepT, T>(-1));
  void spin_node_some(std::shared_ptr<rclcpp::Node> node);
  virtual void spin_some(std::chrono::nanoseconds max_duration = std::chrono::nanoseconds(0));
  virtual void spin_all(std::chrono::nanoseconds max_duration);
  virtual void spin_once(std::chrono::nanoseconds timeout = std::chrono::nanoseconds(-1));
  template<typename FutureT, typename TimeRepT = int64_t, typename TimeT = std::milli>
  FutureReturnCode spin_until_future_complete(
    const FutureT & future,
    std::chrono::duration<TimeRepT, TimeT> timeout = std::chrono::duration<TimeRepT, TimeT>(-1));
  void cancel();
};
namespace executors
{
class SingleThreadedExecutor : public rclcpp::Executor
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(SingleThreadedExecutor)
  explicit SingleThreadedExecutor(const rclcpp::ExecutorOptions & options = rclcpp::ExecutorOptions());
};
class MultiThreadedExecutor : public rclcpp::Executor
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(MultiThreadedExecutor)
  explicit MultiThreadedExecutor(
    const rclcpp::ExecutorOptions & options = rclcpp::ExecutorOptions(), size_t number_of_threads = 0,
    bool yield_before_execute = false,
    std::chrono::nanoseconds timeout = std::chrono::nanoseconds(-1));
  size_t get_number_of_threads();
};
class StaticSingleThreadedExecutor : public rclcpp::Executor
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(StaticSingleThreadedExecutor)
  explicit StaticSingleThreadedExecutor(const rclcpp::ExecutorOptions & options = rclcpp::ExecutorOptions());
};
template<typename FutureT, typename TimeRepT = int64_t, typename TimeT = std::milli>
rclcpp::FutureReturnCode spin_node_until_future_complete(
  rclcpp::Executor & executor, std::shared_ptr<rclcpp::Node> node_ptr, const FutureT & future,
  std::chrono::duration<TimeRepT, TimeT> timeout = std::chrono::duration<TimeRepT, TimeT>(-1));
}  // namespace executors
namespace experimental
{
namespace executors
{
class EventsExecutor : public rclcpp::Executor
{
public:
  explicit EventsExecutor(
    std::unique_ptr<int> events_queue = nullptr, bool execute_timers_separate_thread = false,
    const rclcpp::ExecutorOptions & options = rclcpp::ExecutorOptions());
};
}  // namespace executors
}  // namespace experimental

void spin(rclcpp::node_interfaces::NodeBaseInterface::SharedPtr node_ptr);
void spin(rclcpp::Node::SharedPtr node_ptr);
void spin_some(rclcpp::node_interfaces::NodeBaseInterface::SharedPtr node_ptr);
void spin_some(rclcpp::Node::SharedPtr node_ptr);
template<typename FutureT, typename TimeRepT = int64_t, typename TimeT = std::milli>
rclcpp::FutureReturnCode spin_until_future_complete(
  rclcpp::node_interfaces::NodeBaseInterface::SharedPtr node_ptr, const FutureT & future,
  std::chrono::duration<TimeRepT, TimeT> timeout = std::chrono::duration<TimeRepT, TimeT>(-1));
template<typename NodeT = rclcpp::Node, typename FutureT, typename TimeRepT = int64_t, typename TimeT = std::milli>
rclcpp::FutureReturnCode spin_until_future_complete(
  std::shared_ptr<NodeT> node_ptr, const FutureT & future,
  std::chrono::duration<TimeRepT, TimeT> timeout = std::chrono::duration<TimeRepT, TimeT>(-1));
}  // namespace rclcpp

#endif  // ARCHLOG_ROS2_RCLCPP_HPP_
