// archlog stand-in for rclcpp_lifecycle (ROS 2): declarations only, under the real names.
#ifndef ARCHLOG_ROS2_RCLCPP_LIFECYCLE_HPP_
#define ARCHLOG_ROS2_RCLCPP_LIFECYCLE_HPP_

#include "archlog_ros2/rclcpp.hpp"
#include "lifecycle_msgs/msg/state.hpp"
#include "lifecycle_msgs/msg/transition.hpp"

namespace rclcpp_lifecycle
{
class State
{
public:
  State();
  State(uint8_t id, const std::string & label);
  uint8_t id() const;
  std::string label() const;
};

class Transition
{
public:
  explicit Transition(uint8_t id, const std::string & label = "");
  uint8_t id() const;
  std::string label() const;
};

namespace node_interfaces
{
class LifecycleNodeInterface
{
public:
  enum class CallbackReturn : uint8_t
  {
    SUCCESS = lifecycle_msgs::msg::Transition::TRANSITION_CALLBACK_SUCCESS,
    FAILURE = lifecycle_msgs::msg::Transition::TRANSITION_CALLBACK_FAILURE,
    ERROR = lifecycle_msgs::msg::Transition::TRANSITION_CALLBACK_ERROR
  };
  virtual CallbackReturn on_configure(const State & previous_state);
  virtual CallbackReturn on_cleanup(const State & previous_state);
  virtual CallbackReturn on_shutdown(const State & previous_state);
  virtual CallbackReturn on_activate(const State & previous_state);
  virtual CallbackReturn on_deactivate(const State & previous_state);
  virtual CallbackReturn on_error(const State & previous_state);
  virtual ~LifecycleNodeInterface();
};
}  // namespace node_interfaces

class SimpleManagedEntity
{
public:
  virtual ~SimpleManagedEntity();
  virtual void on_activate();
  virtual void on_deactivate();
  virtual bool is_activated() const;
};

template<typename MessageT, typename Alloc = std::allocator<void>>
class LifecyclePublisher : public SimpleManagedEntity, public rclcpp::Publisher<MessageT, Alloc>
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(LifecyclePublisher)
  void on_activate() override;
  void on_deactivate() override;
};

class LifecycleNode : public node_interfaces::LifecycleNodeInterface,
  public std::enable_shared_from_this<LifecycleNode>
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(LifecycleNode)
  using OnSetParametersCallbackHandle = rclcpp::node_interfaces::OnSetParametersCallbackHandle;
  using OnParametersSetCallbackType = OnSetParametersCallbackHandle::OnParametersSetCallbackType;

  explicit LifecycleNode(
    const std::string & node_name, const rclcpp::NodeOptions & options = rclcpp::NodeOptions(),
    bool enable_communication_interface = true);
  LifecycleNode(
    const std::string & node_name, const std::string & namespace_,
    const rclcpp::NodeOptions & options = rclcpp::NodeOptions(), bool enable_communication_interface = true);
  virtual ~LifecycleNode();

  const char * get_name() const;
  const char * get_namespace() const;
  const char * get_fully_qualified_name() const;
  rclcpp::Logger get_logger() const;
  rclcpp::CallbackGroup::SharedPtr create_callback_group(
    rclcpp::CallbackGroupType group_type, bool automatically_add_to_executor_with_node = true);

  template<typename MessageT, typename AllocatorT = std::allocator<void>>
  std::shared_ptr<rclcpp_lifecycle::LifecyclePublisher<MessageT, AllocatorT>> create_publisher(
    const std::string & topic_name, const rclcpp::QoS & qos,
    const rclcpp::PublisherOptionsWithAllocator<AllocatorT> & options =
    rclcpp::PublisherOptionsWithAllocator<AllocatorT>());

  template<typename MessageT, typename CallbackT, typename AllocatorT = std::allocator<void>,
    typename SubscriptionT = rclcpp::Subscription<MessageT, AllocatorT>>
  std::shared_ptr<SubscriptionT> create_subscription(
    const std::string & topic_name, const rclcpp::QoS & qos, CallbackT && callback,
    const rclcpp::SubscriptionOptionsWithAllocator<AllocatorT> & options =
    rclcpp::SubscriptionOptionsWithAllocator<AllocatorT>());

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
    const std::string & namespace_, const std::map<std::string, ParameterT> & parameters);
  void undeclare_parameter(const std::string & name);
  bool has_parameter(const std::string & name) const;
  rcl_interfaces::msg::SetParametersResult set_parameter(const rclcpp::Parameter & parameter);
  std::vector<rcl_interfaces::msg::SetParametersResult> set_parameters(
    const std::vector<rclcpp::Parameter> & parameters);
  rclcpp::Parameter get_parameter(const std::string & name) const;
  bool get_parameter(const std::string & name, rclcpp::Parameter & parameter) const;
  template<typename ParameterT>
  bool get_parameter(const std::string & name, ParameterT & parameter) const;
  template<typename ParameterT>
  bool get_parameter_or(
    const std::string & name, ParameterT & value, const ParameterT & alternative_value) const;
  std::vector<rclcpp::Parameter> get_parameters(const std::vector<std::string> & names) const;
  template<typename ParameterT>
  bool get_parameters(const std::string & prefix, std::map<std::string, ParameterT> & values) const;
  rcl_interfaces::msg::ParameterDescriptor describe_parameter(const std::string & name) const;
  OnSetParametersCallbackHandle::SharedPtr add_on_set_parameters_callback(OnParametersSetCallbackType callback);
  void remove_on_set_parameters_callback(const OnSetParametersCallbackHandle * const handler);
  rclcpp::node_interfaces::PreSetParametersCallbackHandle::SharedPtr add_pre_set_parameters_callback(
    rclcpp::node_interfaces::PreSetParametersCallbackHandle::PreSetParametersCallbackType callback);
  rclcpp::node_interfaces::PostSetParametersCallbackHandle::SharedPtr add_post_set_parameters_callback(
    rclcpp::node_interfaces::PostSetParametersCallbackHandle::PostSetParametersCallbackType callback);
  void remove_pre_set_parameters_callback(
    const rclcpp::node_interfaces::PreSetParametersCallbackHandle * const handler);
  void remove_post_set_parameters_callback(
    const rclcpp::node_interfaces::PostSetParametersCallbackHandle * const handler);

  std::vector<std::string> get_node_names() const;
  size_t count_publishers(const std::string & topic_name) const;
  size_t count_subscribers(const std::string & topic_name) const;
  rclcpp::Clock::SharedPtr get_clock();
  rclcpp::Clock::ConstSharedPtr get_clock() const;
  rclcpp::Time now() const;

  rclcpp::node_interfaces::NodeBaseInterface::SharedPtr get_node_base_interface();
  rclcpp::node_interfaces::NodeClockInterface::SharedPtr get_node_clock_interface();
  rclcpp::node_interfaces::NodeGraphInterface::SharedPtr get_node_graph_interface();
  rclcpp::node_interfaces::NodeLoggingInterface::SharedPtr get_node_logging_interface();
  rclcpp::node_interfaces::NodeTimersInterface::SharedPtr get_node_timers_interface();
  rclcpp::node_interfaces::NodeTopicsInterface::SharedPtr get_node_topics_interface();
  rclcpp::node_interfaces::NodeServicesInterface::SharedPtr get_node_services_interface();
  rclcpp::node_interfaces::NodeWaitablesInterface::SharedPtr get_node_waitables_interface();
  rclcpp::node_interfaces::NodeParametersInterface::SharedPtr get_node_parameters_interface();
  const rclcpp::NodeOptions & get_node_options() const;

  const State & get_current_state() const;
  std::vector<State> get_available_states() const;
  std::vector<Transition> get_available_transitions() const;
  const State & trigger_transition(const Transition & transition);
  const State & trigger_transition(uint8_t transition_id);
  const State & configure();
  const State & cleanup();
  const State & activate();
  const State & deactivate();
  const State & shutdown();
  bool register_on_configure(std::function<CallbackReturn(const State &)> fcn);
  bool register_on_cleanup(std::function<CallbackReturn(const State &)> fcn);
  bool register_on_shutdown(std::function<CallbackReturn(const State &)> fcn);
  bool register_on_activate(std::function<CallbackReturn(const State &)> fcn);
  bool register_on_deactivate(std::function<CallbackReturn(const State &)> fcn);
  bool register_on_error(std::function<CallbackReturn(const State &)> fcn);
  void add_managed_entity(std::weak_ptr<rclcpp_lifecycle::SimpleManagedEntity> managed_entity);
  void add_timer_handle(std::shared_ptr<rclcpp::TimerBase> timer);
};
}  // namespace rclcpp_lifecycle

#endif  // ARCHLOG_ROS2_RCLCPP_LIFECYCLE_HPP_
