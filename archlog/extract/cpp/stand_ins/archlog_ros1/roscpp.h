// archlog stand-in for roscpp (ROS 1), used when ros/ros.h is not installed: the declarations a
// node's code calls (NodeHandle, its ports, parameters, timers, time, console macros), with the
// qualified names and signatures roscpp has, and no definitions. Written for archlog.
#ifndef ARCHLOG_ROS1_ROSCPP_H
#define ARCHLOG_ROS1_ROSCPP_H
#ifndef BOOST_BIND_GLOBAL_PLACEHOLDERS
#define BOOST_BIND_GLOBAL_PLACEHOLDERS
#endif
#include <boost/bind.hpp>
#include <boost/function.hpp>
#include <boost/make_shared.hpp>
#include <boost/shared_ptr.hpp>
#include <cstdint>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "archlog_ros1/print.h"

namespace XmlRpc
{
class XmlRpcValue
{
public:
  enum Type { TypeInvalid, TypeBoolean, TypeInt, TypeDouble, TypeString, TypeDateTime, TypeBase64, TypeArray,
              TypeStruct };
  XmlRpcValue();
  Type getType() const;
  int size() const;
  bool valid() const;
  bool hasMember(const std::string & name) const;
  XmlRpcValue & operator[](int i);
  XmlRpcValue & operator[](const std::string & key);
  operator bool &();
  operator int &();
  operator double &();
  operator std::string &();
};
}  // namespace XmlRpc

namespace ros
{
typedef std::map<std::string, std::string> M_string;
typedef std::vector<std::string> V_string;
typedef boost::shared_ptr<void const> VoidConstPtr;
typedef boost::shared_ptr<void> VoidPtr;

namespace init_options
{
enum InitOption { NoSigintHandler = 1 << 0, AnonymousName = 1 << 1, NoRosout = 1 << 2 };
}
typedef init_options::InitOption InitOption;

void init(int & argc, char ** argv, const std::string & name, uint32_t options = 0);
void init(const M_string & remappings, const std::string & name, uint32_t options = 0);
void init(const std::vector<std::pair<std::string, std::string>> & remapping_args, const std::string & name,
          uint32_t options = 0);
bool ok();
bool isShuttingDown();
bool isStarted();
void start();
void shutdown();
void requestShutdown();
void waitForShutdown();
void removeROSArgs(int argc, const char * const * argv, V_string & args_out);

class Rate;
class Duration
{
public:
  int32_t sec, nsec;
  Duration();
  explicit Duration(double seconds);
  Duration(int32_t seconds, int32_t nanoseconds);
  explicit Duration(const Rate & rate);
  double toSec() const;
  int64_t toNSec() const;
  bool isZero() const;
  bool sleep() const;
  Duration & fromSec(double seconds);
  Duration & fromNSec(int64_t nanoseconds);
  Duration operator+(const Duration & other) const;
  Duration operator-(const Duration & other) const;
  Duration operator-() const;
  Duration operator*(double scale) const;
  Duration & operator+=(const Duration & other);
  Duration & operator-=(const Duration & other);
  bool operator==(const Duration & other) const;
  bool operator!=(const Duration & other) const;
  bool operator<(const Duration & other) const;
  bool operator>(const Duration & other) const;
  bool operator<=(const Duration & other) const;
  bool operator>=(const Duration & other) const;
};
class WallDuration : public Duration
{
public:
  WallDuration();
  explicit WallDuration(double seconds);
  WallDuration(int32_t seconds, int32_t nanoseconds);
};

class Time
{
public:
  uint32_t sec, nsec;
  Time();
  Time(uint32_t seconds, uint32_t nanoseconds);
  explicit Time(double seconds);
  static Time now();
  static bool sleepUntil(const Time & end);
  static void init();
  static bool isValid();
  static bool waitForValid();
  double toSec() const;
  uint64_t toNSec() const;
  bool isZero() const;
  Time & fromSec(double seconds);
  Time & fromNSec(uint64_t nanoseconds);
  Duration operator-(const Time & other) const;
  Time operator+(const Duration & offset) const;
  Time operator-(const Duration & offset) const;
  Time & operator+=(const Duration & offset);
  Time & operator-=(const Duration & offset);
  bool operator==(const Time & other) const;
  bool operator!=(const Time & other) const;
  bool operator<(const Time & other) const;
  bool operator>(const Time & other) const;
  bool operator<=(const Time & other) const;
  bool operator>=(const Time & other) const;
};
typedef Time WallTime;
typedef Time SteadyTime;
const Time TIME_MIN(0, 1);
const Time TIME_MAX(4294967295u, 999999999u);

class Rate
{
public:
  explicit Rate(double frequency);
  explicit Rate(const Duration & period);
  bool sleep();
  void reset();
  Duration cycleTime() const;
  Duration expectedCycleTime() const;
};
class WallRate : public Rate
{
public:
  explicit WallRate(double frequency);
  explicit WallRate(const Duration & period);
};

struct TimerEvent
{
  Time last_expected, last_real, current_expected, current_real;
  struct { WallDuration last_duration; } profile;
};
struct WallTimerEvent : TimerEvent {};
struct SteadyTimerEvent : TimerEvent {};
typedef boost::function<void(const TimerEvent &)> TimerCallback;
typedef boost::function<void(const WallTimerEvent &)> WallTimerCallback;
typedef boost::function<void(const SteadyTimerEvent &)> SteadyTimerCallback;

class Timer
{
public:
  Timer();
  void start();
  void stop();
  bool hasPending();
  bool hasStarted() const;
  bool isValid();
  void setPeriod(const Duration & period, bool reset = true);
  operator void *();
};
class WallTimer : public Timer {};
class SteadyTimer : public Timer {};

class Publisher
{
public:
  Publisher();
  template<class M> void publish(const boost::shared_ptr<M> & message) const;
  template<class M> void publish(const M & message) const;
  void shutdown();
  std::string getTopic() const;
  uint32_t getNumSubscribers() const;
  bool isLatched() const;
  operator void *() const;
  bool operator<(const Publisher & rhs) const;
  bool operator==(const Publisher & rhs) const;
  bool operator!=(const Publisher & rhs) const;
};

class SingleSubscriberPublisher
{
public:
  template<class M> void publish(const boost::shared_ptr<M const> & message) const;
  template<class M> void publish(const M & message) const;
  std::string getTopic() const;
  std::string getSubscriberName() const;
};
typedef boost::function<void(const SingleSubscriberPublisher &)> SubscriberStatusCallback;

class Subscriber
{
public:
  Subscriber();
  void shutdown();
  std::string getTopic() const;
  uint32_t getNumPublishers() const;
  operator void *() const;
  bool operator<(const Subscriber & rhs) const;
  bool operator==(const Subscriber & rhs) const;
  bool operator!=(const Subscriber & rhs) const;
};

class ServiceServer
{
public:
  ServiceServer();
  void shutdown();
  std::string getService() const;
  operator void *() const;
};

class ServiceClient
{
public:
  ServiceClient();
  template<class Service> bool call(Service & service);
  template<class MReq, class MRes> bool call(MReq & request, MRes & response);
  bool isValid() const;
  bool isPersistent() const;
  void shutdown();
  bool waitForExistence(Duration timeout = Duration(-1));
  bool exists();
  std::string getService();
  operator void *() const;
};

template<class MReq, class MRes> class ServiceEvent
{
public:
  const MReq & getRequest() const;
  MRes & getResponse() const;
  const std::string & getCallerName() const;
};

template<class M> class MessageEvent
{
public:
  MessageEvent();
  const boost::shared_ptr<M const> & getConstMessage() const;
  boost::shared_ptr<M> getMessage() const;
  const std::string & getPublisherName() const;
  Time getReceiptTime() const;
  bool nonConstWillCopy() const;
};

class TransportHints
{
public:
  TransportHints();
  TransportHints & reliable();
  TransportHints & tcp();
  TransportHints & tcpNoDelay(bool nodelay = true);
  TransportHints & unreliable();
  TransportHints & udp();
  TransportHints & maxDatagramSize(int size);
};

class CallbackQueueInterface
{
public:
  virtual ~CallbackQueueInterface();
};
class CallbackQueue : public CallbackQueueInterface
{
public:
  explicit CallbackQueue(bool enabled = true);
  void callAvailable();
  void callAvailable(WallDuration timeout);
  void callOne();
  void callOne(WallDuration timeout);
  void clear();
  bool empty();
  bool isEnabled();
  void enable();
  void disable();
};
CallbackQueue * getGlobalCallbackQueue();

class Spinner
{
public:
  virtual ~Spinner();
  virtual void spin(CallbackQueue * queue = 0) = 0;
};
class SingleThreadedSpinner : public Spinner
{
public:
  void spin(CallbackQueue * queue = 0) override;
};
class MultiThreadedSpinner : public Spinner
{
public:
  explicit MultiThreadedSpinner(uint32_t thread_count = 0);
  void spin(CallbackQueue * queue = 0) override;
};
class AsyncSpinner
{
public:
  explicit AsyncSpinner(uint32_t thread_count);
  AsyncSpinner(uint32_t thread_count, CallbackQueue * queue);
  bool canStart();
  void start();
  void stop();
};
void spin();
void spin(Spinner & spinner);
void spinOnce();

class NodeHandle
{
public:
  NodeHandle(const std::string & ns = std::string(), const M_string & remappings = M_string());
  NodeHandle(const NodeHandle & parent, const std::string & ns);
  NodeHandle(const NodeHandle & parent, const std::string & ns, const M_string & remappings);
  NodeHandle(const NodeHandle & rhs);
  ~NodeHandle();
  NodeHandle & operator=(const NodeHandle & rhs);

  void setCallbackQueue(CallbackQueueInterface * queue);
  CallbackQueueInterface * getCallbackQueue() const;
  const std::string & getNamespace() const;
  const std::string & getUnresolvedNamespace() const;
  std::string resolveName(const std::string & name, bool remap = true) const;
  bool ok() const;
  void shutdown();

  template<class M> Publisher advertise(const std::string & topic, uint32_t queue_size, bool latch = false);
  template<class M> Publisher advertise(const std::string & topic, uint32_t queue_size,
                                        const SubscriberStatusCallback & connect_cb,
                                        const SubscriberStatusCallback & disconnect_cb = SubscriberStatusCallback(),
                                        const VoidConstPtr & tracked_object = VoidConstPtr(), bool latch = false);

  template<class M, class T> Subscriber subscribe(const std::string & topic, uint32_t queue_size, void (T::*fp)(M),
                                                  T * obj, const TransportHints & hints = TransportHints());
  template<class M, class T> Subscriber subscribe(const std::string & topic, uint32_t queue_size,
                                                  void (T::*fp)(M) const, T * obj,
                                                  const TransportHints & hints = TransportHints());
  template<class M, class T> Subscriber subscribe(const std::string & topic, uint32_t queue_size,
                                                  void (T::*fp)(const boost::shared_ptr<M const> &), T * obj,
                                                  const TransportHints & hints = TransportHints());
  template<class M, class T> Subscriber subscribe(const std::string & topic, uint32_t queue_size,
                                                  void (T::*fp)(const boost::shared_ptr<M const> &) const, T * obj,
                                                  const TransportHints & hints = TransportHints());
  template<class M, class T> Subscriber subscribe(const std::string & topic, uint32_t queue_size, void (T::*fp)(M),
                                                  const boost::shared_ptr<T> & obj,
                                                  const TransportHints & hints = TransportHints());
  template<class M, class T> Subscriber subscribe(const std::string & topic, uint32_t queue_size,
                                                  void (T::*fp)(const boost::shared_ptr<M const> &),
                                                  const boost::shared_ptr<T> & obj,
                                                  const TransportHints & hints = TransportHints());
  template<class M> Subscriber subscribe(const std::string & topic, uint32_t queue_size, void (*fp)(M),
                                         const TransportHints & hints = TransportHints());
  template<class M> Subscriber subscribe(const std::string & topic, uint32_t queue_size,
                                         void (*fp)(const boost::shared_ptr<M const> &),
                                         const TransportHints & hints = TransportHints());
  template<class M> Subscriber subscribe(const std::string & topic, uint32_t queue_size,
                                         const boost::function<void(const boost::shared_ptr<M const> &)> & callback,
                                         const VoidConstPtr & tracked_object = VoidConstPtr(),
                                         const TransportHints & hints = TransportHints());
  template<class M, class C> Subscriber subscribe(const std::string & topic, uint32_t queue_size,
                                                  const boost::function<void(C)> & callback,
                                                  const VoidConstPtr & tracked_object = VoidConstPtr(),
                                                  const TransportHints & hints = TransportHints());

  template<class T, class MReq, class MRes> ServiceServer advertiseService(const std::string & service,
                                                                           bool (T::*srv_func)(MReq &, MRes &),
                                                                           T * obj);
  template<class T, class MReq, class MRes> ServiceServer advertiseService(
    const std::string & service, bool (T::*srv_func)(ServiceEvent<MReq, MRes> &), T * obj);
  template<class T, class MReq, class MRes> ServiceServer advertiseService(const std::string & service,
                                                                           bool (T::*srv_func)(MReq &, MRes &),
                                                                           const boost::shared_ptr<T> & obj);
  template<class MReq, class MRes> ServiceServer advertiseService(const std::string & service,
                                                                  bool (*srv_func)(MReq &, MRes &));
  template<class MReq, class MRes> ServiceServer advertiseService(
    const std::string & service, const boost::function<bool(MReq &, MRes &)> & callback,
    const VoidConstPtr & tracked_object = VoidConstPtr());
  template<class S> ServiceServer advertiseService(const std::string & service,
                                                   const boost::function<bool(S &)> & callback,
                                                   const VoidConstPtr & tracked_object = VoidConstPtr());

  template<class MReq, class MRes> ServiceClient serviceClient(const std::string & service_name,
                                                               bool persistent = false,
                                                               const M_string & header_values = M_string());
  template<class Service> ServiceClient serviceClient(const std::string & service_name, bool persistent = false,
                                                      const M_string & header_values = M_string());

  Timer createTimer(Duration period, const TimerCallback & callback, bool oneshot = false,
                    bool autostart = true) const;
  template<class T> Timer createTimer(Duration period, void (T::*callback)(const TimerEvent &), T * obj,
                                      bool oneshot = false, bool autostart = true) const;
  template<class T> Timer createTimer(Duration period, void (T::*callback)(const TimerEvent &) const, T * obj,
                                      bool oneshot = false, bool autostart = true) const;
  template<class T> Timer createTimer(Duration period, void (T::*callback)(const TimerEvent &),
                                      const boost::shared_ptr<T> & obj, bool oneshot = false,
                                      bool autostart = true) const;
  WallTimer createWallTimer(WallDuration period, const WallTimerCallback & callback, bool oneshot = false,
                            bool autostart = true) const;
  template<class T> WallTimer createWallTimer(WallDuration period, void (T::*callback)(const WallTimerEvent &),
                                              T * obj, bool oneshot = false, bool autostart = true) const;
  SteadyTimer createSteadyTimer(WallDuration period, const SteadyTimerCallback & callback, bool oneshot = false,
                                bool autostart = true) const;
  template<class T> SteadyTimer createSteadyTimer(WallDuration period,
                                                  void (T::*callback)(const SteadyTimerEvent &), T * obj,
                                                  bool oneshot = false, bool autostart = true) const;

  template<class T> bool getParam(const std::string & key, T & value) const;
  template<class T> bool getParamCached(const std::string & key, T & value) const;
  template<class T> void setParam(const std::string & key, const T & value) const;
  void setParam(const std::string & key, const char * value) const;
  bool hasParam(const std::string & key) const;
  bool deleteParam(const std::string & key) const;
  bool searchParam(const std::string & key, std::string & result) const;
  bool getParamNames(std::vector<std::string> & keys) const;
  template<class T> bool param(const std::string & param_name, T & param_val, const T & default_val) const;
  bool param(const std::string & param_name, std::string & param_val, const char * default_val) const;
  template<class T> T param(const std::string & param_name, const T & default_val);
  std::string param(const std::string & param_name, const char * default_val);
};

namespace this_node
{
const std::string & getName();
const std::string & getNamespace();
void getAdvertisedTopics(V_string & topics);
void getSubscribedTopics(V_string & topics);
}  // namespace this_node

namespace names
{
std::string append(const std::string & left, const std::string & right);
std::string clean(const std::string & name);
std::string remap(const std::string & name);
std::string resolve(const std::string & name, bool remap = true);
std::string resolve(const std::string & ns, const std::string & name, bool remap = true);
std::string parentNamespace(const std::string & name);
bool validate(const std::string & name, std::string & error);
}  // namespace names

namespace param
{
template<class T> bool get(const std::string & key, T & value);
template<class T> bool getCached(const std::string & key, T & value);
template<class T> void set(const std::string & key, const T & value);
void set(const std::string & key, const char * value);
bool has(const std::string & key);
bool del(const std::string & key);
bool search(const std::string & key, std::string & result);
bool search(const std::string & ns, const std::string & key, std::string & result);
bool getParamNames(std::vector<std::string> & keys);
template<class T> bool param(const std::string & param_name, T & param_val, const T & default_val);
bool param(const std::string & param_name, std::string & param_val, const char * default_val);
template<class T> T param(const std::string & param_name, const T & default_val);
}  // namespace param

namespace service
{
template<class Service> bool call(const std::string & service_name, Service & service);
template<class MReq, class MRes> bool call(const std::string & service_name, MReq & request, MRes & response);
bool waitForService(const std::string & service_name, int32_t timeout = -1);
bool waitForService(const std::string & service_name, Duration timeout);
bool exists(const std::string & service_name, bool print_failure_reason);
template<class MReq, class MRes> ServiceClient createClient(const std::string & service_name,
                                                            bool persistent = false,
                                                            const M_string & header_values = M_string());
}  // namespace service

namespace topic
{
template<class M> boost::shared_ptr<M const> waitForMessage(const std::string & topic);
template<class M> boost::shared_ptr<M const> waitForMessage(const std::string & topic, Duration timeout);
template<class M> boost::shared_ptr<M const> waitForMessage(const std::string & topic, NodeHandle & nh);
template<class M> boost::shared_ptr<M const> waitForMessage(const std::string & topic, NodeHandle & nh,
                                                          Duration timeout);
}  // namespace topic

namespace master
{
bool check();
const std::string & getHost();
uint32_t getPort();
const std::string & getURI();
}  // namespace master

class Exception : public std::runtime_error
{
public:
  explicit Exception(const std::string & what);
};
class InvalidNameException : public Exception
{
public:
  explicit InvalidNameException(const std::string & what);
};
}  // namespace ros

// rosconsole: every argument is evaluated, nothing is printed
#define ROS_DEBUG(...) ARCHLOG_ROS_PRINT(__VA_ARGS__)
#define ROS_INFO(...) ARCHLOG_ROS_PRINT(__VA_ARGS__)
#define ROS_WARN(...) ARCHLOG_ROS_PRINT(__VA_ARGS__)
#define ROS_ERROR(...) ARCHLOG_ROS_PRINT(__VA_ARGS__)
#define ROS_FATAL(...) ARCHLOG_ROS_PRINT(__VA_ARGS__)
#define ROS_DEBUG_STREAM(args) ARCHLOG_ROS_STREAM(args)
#define ROS_INFO_STREAM(args) ARCHLOG_ROS_STREAM(args)
#define ROS_WARN_STREAM(args) ARCHLOG_ROS_STREAM(args)
#define ROS_ERROR_STREAM(args) ARCHLOG_ROS_STREAM(args)
#define ROS_FATAL_STREAM(args) ARCHLOG_ROS_STREAM(args)
#define ROS_DEBUG_ONCE(...) ARCHLOG_ROS_PRINT(__VA_ARGS__)
#define ROS_INFO_ONCE(...) ARCHLOG_ROS_PRINT(__VA_ARGS__)
#define ROS_WARN_ONCE(...) ARCHLOG_ROS_PRINT(__VA_ARGS__)
#define ROS_ERROR_ONCE(...) ARCHLOG_ROS_PRINT(__VA_ARGS__)
#define ROS_FATAL_ONCE(...) ARCHLOG_ROS_PRINT(__VA_ARGS__)
#define ROS_DEBUG_STREAM_ONCE(args) ARCHLOG_ROS_STREAM(args)
#define ROS_INFO_STREAM_ONCE(args) ARCHLOG_ROS_STREAM(args)
#define ROS_WARN_STREAM_ONCE(args) ARCHLOG_ROS_STREAM(args)
#define ROS_ERROR_STREAM_ONCE(args) ARCHLOG_ROS_STREAM(args)
#define ROS_FATAL_STREAM_ONCE(args) ARCHLOG_ROS_STREAM(args)
#define ROS_DEBUG_THROTTLE(period, ...) ARCHLOG_ROS_PRINT(period, __VA_ARGS__)
#define ROS_INFO_THROTTLE(period, ...) ARCHLOG_ROS_PRINT(period, __VA_ARGS__)
#define ROS_WARN_THROTTLE(period, ...) ARCHLOG_ROS_PRINT(period, __VA_ARGS__)
#define ROS_ERROR_THROTTLE(period, ...) ARCHLOG_ROS_PRINT(period, __VA_ARGS__)
#define ROS_FATAL_THROTTLE(period, ...) ARCHLOG_ROS_PRINT(period, __VA_ARGS__)
#define ROS_DEBUG_STREAM_THROTTLE(period, args) ARCHLOG_ROS_STREAM(period << args)
#define ROS_INFO_STREAM_THROTTLE(period, args) ARCHLOG_ROS_STREAM(period << args)
#define ROS_WARN_STREAM_THROTTLE(period, args) ARCHLOG_ROS_STREAM(period << args)
#define ROS_ERROR_STREAM_THROTTLE(period, args) ARCHLOG_ROS_STREAM(period << args)
#define ROS_FATAL_STREAM_THROTTLE(period, args) ARCHLOG_ROS_STREAM(period << args)
#define ROS_DEBUG_NAMED(name, ...) ARCHLOG_ROS_PRINT(name, __VA_ARGS__)
#define ROS_INFO_NAMED(name, ...) ARCHLOG_ROS_PRINT(name, __VA_ARGS__)
#define ROS_WARN_NAMED(name, ...) ARCHLOG_ROS_PRINT(name, __VA_ARGS__)
#define ROS_ERROR_NAMED(name, ...) ARCHLOG_ROS_PRINT(name, __VA_ARGS__)
#define ROS_FATAL_NAMED(name, ...) ARCHLOG_ROS_PRINT(name, __VA_ARGS__)
#define ROS_DEBUG_STREAM_NAMED(name, args) ARCHLOG_ROS_STREAM(name << args)
#define ROS_INFO_STREAM_NAMED(name, args) ARCHLOG_ROS_STREAM(name << args)
#define ROS_WARN_STREAM_NAMED(name, args) ARCHLOG_ROS_STREAM(name << args)
#define ROS_ERROR_STREAM_NAMED(name, args) ARCHLOG_ROS_STREAM(name << args)
#define ROS_FATAL_STREAM_NAMED(name, args) ARCHLOG_ROS_STREAM(name << args)
#define ROS_DEBUG_COND(cond, ...) ARCHLOG_ROS_PRINT(cond, __VA_ARGS__)
#define ROS_INFO_COND(cond, ...) ARCHLOG_ROS_PRINT(cond, __VA_ARGS__)
#define ROS_WARN_COND(cond, ...) ARCHLOG_ROS_PRINT(cond, __VA_ARGS__)
#define ROS_ERROR_COND(cond, ...) ARCHLOG_ROS_PRINT(cond, __VA_ARGS__)
#define ROS_FATAL_COND(cond, ...) ARCHLOG_ROS_PRINT(cond, __VA_ARGS__)
#define ROS_DEBUG_DELAYED_THROTTLE(period, ...) ARCHLOG_ROS_PRINT(period, __VA_ARGS__)
#define ROS_INFO_DELAYED_THROTTLE(period, ...) ARCHLOG_ROS_PRINT(period, __VA_ARGS__)
#define ROS_WARN_DELAYED_THROTTLE(period, ...) ARCHLOG_ROS_PRINT(period, __VA_ARGS__)
#define ROS_ERROR_DELAYED_THROTTLE(period, ...) ARCHLOG_ROS_PRINT(period, __VA_ARGS__)
#define ROS_ASSERT(cond) ARCHLOG_ROS_PRINT(cond)
#define ROS_ASSERT_MSG(cond, ...) ARCHLOG_ROS_PRINT(cond, __VA_ARGS__)
#define ROS_BREAK() ARCHLOG_ROS_PRINT(0)
#endif
