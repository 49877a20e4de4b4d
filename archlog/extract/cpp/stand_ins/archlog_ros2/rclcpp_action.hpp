// archlog stand-in for rclcpp_action (ROS 2): declarations only, under the real names.
#ifndef ARCHLOG_ROS2_RCLCPP_ACTION_HPP_
#define ARCHLOG_ROS2_RCLCPP_ACTION_HPP_

#include "archlog_ros2/rclcpp.hpp"
#include "action_msgs/msg/goal_status.hpp"
#include "action_msgs/srv/cancel_goal.hpp"

extern "C"
{
typedef struct rcl_action_server_options_s
{
  rmw_qos_profile_t goal_service_qos;
  rmw_qos_profile_t cancel_service_qos;
  rmw_qos_profile_t result_service_qos;
  rmw_qos_profile_t feedback_topic_qos;
  rmw_qos_profile_t status_topic_qos;
  rcl_duration_value_t result_timeout;
} rcl_action_server_options_t;
typedef struct rcl_action_client_options_s
{
  rmw_qos_profile_t goal_service_qos;
  rmw_qos_profile_t result_service_qos;
  rmw_qos_profile_t cancel_service_qos;
  rmw_qos_profile_t feedback_topic_qos;
  rmw_qos_profile_t status_topic_qos;
} rcl_action_client_options_t;
rcl_action_server_options_t rcl_action_server_get_default_options(void);
rcl_action_client_options_t rcl_action_client_get_default_options(void);
}

namespace rclcpp_action
{
using GoalUUID = std::array<uint8_t, 16>;
enum class GoalResponse : int8_t { REJECT = 1, ACCEPT_AND_EXECUTE = 2, ACCEPT_AND_DEFER = 3 };
enum class CancelResponse : int8_t { REJECT = 1, ACCEPT = 2 };
enum class ResultCode : int8_t
{
  UNKNOWN = action_msgs::msg::GoalStatus::STATUS_UNKNOWN,
  SUCCEEDED = action_msgs::msg::GoalStatus::STATUS_SUCCEEDED,
  CANCELED = action_msgs::msg::GoalStatus::STATUS_CANCELED,
  ABORTED = action_msgs::msg::GoalStatus::STATUS_ABORTED
};
std::string to_string(const GoalUUID & goal_id);

class ServerBase
{
public:
  virtual ~ServerBase();
};
template<typename ActionT>
class ServerGoalHandle
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(ServerGoalHandle)
  bool is_canceling() const;
  bool is_active() const;
  bool is_executing() const;
  void publish_feedback(std::shared_ptr<typename ActionT::Feedback> feedback_msg);
  void abort(typename ActionT::Result::SharedPtr result_msg);
  void succeed(typename ActionT::Result::SharedPtr result_msg);
  void canceled(typename ActionT::Result::SharedPtr result_msg);
  void execute();
  const std::shared_ptr<const typename ActionT::Goal> get_goal() const;
  const GoalUUID & get_goal_id() const;
};
template<typename ActionT>
class Server : public ServerBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Server)
  using GoalCallback = std::function<GoalResponse(const GoalUUID &, std::shared_ptr<const typename ActionT::Goal>)>;
  using CancelCallback = std::function<CancelResponse(std::shared_ptr<ServerGoalHandle<ActionT>>)>;
  using AcceptedCallback = std::function<void (std::shared_ptr<ServerGoalHandle<ActionT>>)>;
};

// rclcpp_action takes the callbacks as std::function (Server<ActionT>::GoalCallback...); taken
// here as they come, so that a callback whose body uses a field a stand-in message lacks does
// not make the whole call unresolved.
template<typename ActionT, typename NodeT, typename GoalCallbackT, typename CancelCallbackT,
  typename AcceptedCallbackT>
typename Server<ActionT>::SharedPtr create_server(
  NodeT node, const std::string & name, GoalCallbackT && handle_goal, CancelCallbackT && handle_cancel,
  AcceptedCallbackT && handle_accepted,
  const rcl_action_server_options_t & options = rcl_action_server_get_default_options(),
  rclcpp::CallbackGroup::SharedPtr group = nullptr);
template<typename ActionT>
typename Server<ActionT>::SharedPtr create_server(
  rclcpp::node_interfaces::NodeBaseInterface::SharedPtr node_base_interface,
  rclcpp::node_interfaces::NodeClockInterface::SharedPtr node_clock_interface,
  rclcpp::node_interfaces::NodeLoggingInterface::SharedPtr node_logging_interface,
  rclcpp::node_interfaces::NodeWaitablesInterface::SharedPtr node_waitables_interface,
  const std::string & name, typename Server<ActionT>::GoalCallback handle_goal,
  typename Server<ActionT>::CancelCallback handle_cancel,
  typename Server<ActionT>::AcceptedCallback handle_accepted,
  const rcl_action_server_options_t & options = rcl_action_server_get_default_options(),
  rclcpp::CallbackGroup::SharedPtr group = nullptr);

template<typename ActionT>
class ClientGoalHandle
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS_NOT_COPYABLE(ClientGoalHandle)
  using Feedback = typename ActionT::Feedback;
  using Result = typename ActionT::Result;
  struct WrappedResult
  {
    GoalUUID goal_id;
    ResultCode code;
    typename ActionT::Result::SharedPtr result;
  };
  using FeedbackCallback =
    std::function<void (typename ClientGoalHandle<ActionT>::SharedPtr, const std::shared_ptr<const Feedback>)>;
  using ResultCallback = std::function<void (const WrappedResult & result)>;
  const GoalUUID & get_goal_id() const;
  rclcpp::Time get_goal_stamp() const;
  int8_t get_status();
  bool is_feedback_aware();
  bool is_result_aware();
};
class ClientBase
{
public:
  virtual ~ClientBase();
  bool action_server_is_ready() const;
  template<typename RepT = int64_t, typename RatioT = std::milli>
  bool wait_for_action_server(std::chrono::duration<RepT, RatioT> timeout = std::chrono::duration<RepT, RatioT>(-1));
};
template<typename ActionT>
class Client : public ClientBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS_NOT_COPYABLE(Client<ActionT>)
  using Goal = typename ActionT::Goal;
  using Feedback = typename ActionT::Feedback;
  using GoalHandle = ClientGoalHandle<ActionT>;
  using WrappedResult = typename GoalHandle::WrappedResult;
  using GoalResponseCallback = std::function<void (typename GoalHandle::SharedPtr)>;
  using FeedbackCallback = typename GoalHandle::FeedbackCallback;
  using ResultCallback = typename GoalHandle::ResultCallback;
  using CancelRequest = typename action_msgs::srv::CancelGoal::Request;
  using CancelResponse = typename action_msgs::srv::CancelGoal::Response;
  using CancelCallback = std::function<void (typename CancelResponse::SharedPtr)>;
  struct SendGoalOptions
  {
    SendGoalOptions();
    GoalResponseCallback goal_response_callback;
    FeedbackCallback feedback_callback;
    ResultCallback result_callback;
  };
  std::shared_future<typename GoalHandle::SharedPtr> async_send_goal(
    const Goal & goal, const SendGoalOptions & options = SendGoalOptions());
  std::shared_future<WrappedResult> async_get_result(
    typename GoalHandle::SharedPtr goal_handle, ResultCallback result_callback = nullptr);
  std::shared_future<typename CancelResponse::SharedPtr> async_cancel_goal(
    typename GoalHandle::SharedPtr goal_handle, CancelCallback cancel_callback = nullptr);
  std::shared_future<typename CancelResponse::SharedPtr> async_cancel_all_goals(
    CancelCallback cancel_callback = nullptr);
};

template<typename ActionT, typename NodeT>
typename Client<ActionT>::SharedPtr create_client(
  NodeT node, const std::string & name, rclcpp::CallbackGroup::SharedPtr group = nullptr,
  const rcl_action_client_options_t & options = rcl_action_client_get_default_options());
template<typename ActionT>
typename Client<ActionT>::SharedPtr create_client(
  rclcpp::node_interfaces::NodeBaseInterface::SharedPtr node_base_interface,
  rclcpp::node_interfaces::NodeGraphInterface::SharedPtr node_graph_interface,
  rclcpp::node_interfaces::NodeLoggingInterface::SharedPtr node_logging_interface,
  rclcpp::node_interfaces::NodeWaitablesInterface::SharedPtr node_waitables_interface,
  const std::string & name, rclcpp::CallbackGroup::SharedPtr group = nullptr,
  const rcl_action_client_options_t & options = rcl_action_client_get_default_options());
}  // namespace rclcpp_action

#endif  // ARCHLOG_ROS2_RCLCPP_ACTION_HPP_
