// archlog stand-in for message_filters (ROS 1): subscribers and synchronizers of up to five
// inputs. Written for archlog: declarations only.
#ifndef ARCHLOG_ROS1_MESSAGE_FILTERS_H
#define ARCHLOG_ROS1_MESSAGE_FILTERS_H
#include <ros/ros.h>

namespace message_filters
{
struct NullType {};
class Connection
{
public:
  void disconnect();
};

template<class M> class SimpleFilter
{
public:
  template<class C> Connection registerCallback(const C & callback);
  template<class P> Connection registerCallback(void (*callback)(P));
  template<class T, class P> Connection registerCallback(void (T::*callback)(P), T * t);
};

template<class M> class Subscriber : public SimpleFilter<M>
{
public:
  Subscriber();
  Subscriber(ros::NodeHandle & nh, const std::string & topic, uint32_t queue_size,
             const ros::TransportHints & transport_hints = ros::TransportHints(),
             ros::CallbackQueueInterface * callback_queue = 0);
  void subscribe(ros::NodeHandle & nh, const std::string & topic, uint32_t queue_size,
                 const ros::TransportHints & transport_hints = ros::TransportHints(),
                 ros::CallbackQueueInterface * callback_queue = 0);
  void subscribe();
  void unsubscribe();
  std::string getTopic() const;
  const ros::Subscriber & getSubscriber() const;
};

template<class M0, class M1, class M2 = NullType, class M3 = NullType, class M4 = NullType>
class TimeSynchronizer : public SimpleFilter<M0>
{
public:
  template<class F0, class F1> TimeSynchronizer(F0 & f0, F1 & f1, uint32_t queue_size);
  template<class F0, class F1, class F2> TimeSynchronizer(F0 & f0, F1 & f1, F2 & f2, uint32_t queue_size);
  template<class F0, class F1, class F2, class F3>
  TimeSynchronizer(F0 & f0, F1 & f1, F2 & f2, F3 & f3, uint32_t queue_size);
  explicit TimeSynchronizer(uint32_t queue_size);
  template<class F0, class F1> void connectInput(F0 & f0, F1 & f1);
  template<class F0, class F1, class F2> void connectInput(F0 & f0, F1 & f1, F2 & f2);
};

namespace sync_policies
{
template<class M0, class M1, class M2 = NullType, class M3 = NullType, class M4 = NullType> class ApproximateTime
{
public:
  explicit ApproximateTime(uint32_t queue_size);
  void setMaxIntervalDuration(const ros::Duration & max_interval_duration);
  void setAgePenalty(double age_penalty);
};
template<class M0, class M1, class M2 = NullType, class M3 = NullType, class M4 = NullType> class ExactTime
{
public:
  explicit ExactTime(uint32_t queue_size);
};
}  // namespace sync_policies

template<class Policy> class Synchronizer : public SimpleFilter<Policy>
{
public:
  template<class F0, class F1> Synchronizer(F0 & f0, F1 & f1);
  template<class F0, class F1> Synchronizer(const Policy & policy, F0 & f0, F1 & f1);
  template<class F0, class F1, class F2> Synchronizer(const Policy & policy, F0 & f0, F1 & f1, F2 & f2);
  template<class F0, class F1, class F2, class F3>
  Synchronizer(const Policy & policy, F0 & f0, F1 & f1, F2 & f2, F3 & f3);
  explicit Synchronizer(const Policy & policy);
  template<class F0, class F1> void connectInput(F0 & f0, F1 & f1);
  template<class F0, class F1, class F2> void connectInput(F0 & f0, F1 & f1, F2 & f2);
};
}  // namespace message_filters
#endif
