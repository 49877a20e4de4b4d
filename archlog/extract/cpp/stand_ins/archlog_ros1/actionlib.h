// archlog stand-in for actionlib's simple server and client (ROS 1). Written for archlog:
// declarations only. An action type FooAction names its parts as generated headers do
// (_action_goal_type::_goal_type...).
#ifndef ARCHLOG_ROS1_ACTIONLIB_H
#define ARCHLOG_ROS1_ACTIONLIB_H
#include <ros/ros.h>

namespace actionlib
{
// the types of an action's parts, as actionlib's own ACTION_DEFINITION names them
#define ACTION_DEFINITION(ActionSpec) \
  typedef typename ActionSpec::_action_goal_type::_goal_type Goal; \
  typedef typename ActionSpec::_action_result_type::_result_type Result; \
  typedef typename ActionSpec::_action_feedback_type::_feedback_type Feedback; \
  typedef boost::shared_ptr<const Goal> GoalConstPtr; \
  typedef boost::shared_ptr<const Result> ResultConstPtr; \
  typedef boost::shared_ptr<const Feedback> FeedbackConstPtr;

template<class ActionSpec> class SimpleActionServer
{
public:
  ACTION_DEFINITION(ActionSpec)
  typedef boost::function<void(const GoalConstPtr &)> ExecuteCallback;

  SimpleActionServer(std::string name, ExecuteCallback execute_callback, bool auto_start);
  SimpleActionServer(std::string name, bool auto_start);
  SimpleActionServer(ros::NodeHandle n, std::string name, ExecuteCallback execute_callback, bool auto_start);
  SimpleActionServer(ros::NodeHandle n, std::string name, bool auto_start);
  ~SimpleActionServer();
  GoalConstPtr acceptNewGoal();
  bool isNewGoalAvailable();
  bool isPreemptRequested();
  bool isActive();
  void setSucceeded(const Result & result = Result(), const std::string & text = std::string(""));
  void setAborted(const Result & result = Result(), const std::string & text = std::string(""));
  void setPreempted(const Result & result = Result(), const std::string & text = std::string(""));
  void publishFeedback(const Feedback & feedback);
  void publishFeedback(const FeedbackConstPtr & feedback);
  void registerGoalCallback(boost::function<void()> cb);
  void registerPreemptCallback(boost::function<void()> cb);
  void start();
  void shutdown();
};

class SimpleClientGoalState
{
public:
  enum StateEnum { PENDING, ACTIVE, RECALLED, REJECTED, PREEMPTED, ABORTED, SUCCEEDED, LOST };
  SimpleClientGoalState(const StateEnum & state, const std::string & text = std::string(""));
  bool operator==(const SimpleClientGoalState::StateEnum & rhs) const;
  bool operator==(const SimpleClientGoalState & rhs) const;
  bool operator!=(const SimpleClientGoalState::StateEnum & rhs) const;
  bool operator!=(const SimpleClientGoalState & rhs) const;
  bool isDone() const;
  std::string getText() const;
  std::string toString() const;
  StateEnum state_;
  std::string text_;
};

template<class ActionSpec> class SimpleActionClient
{
public:
  ACTION_DEFINITION(ActionSpec)
  typedef boost::function<void(const SimpleClientGoalState &, const ResultConstPtr &)> SimpleDoneCallback;
  typedef boost::function<void()> SimpleActiveCallback;
  typedef boost::function<void(const FeedbackConstPtr &)> SimpleFeedbackCallback;

  SimpleActionClient(const std::string & name, bool spin_thread = true);
  SimpleActionClient(ros::NodeHandle & n, const std::string & name, bool spin_thread = true);
  ~SimpleActionClient();
  bool waitForServer(const ros::Duration & timeout = ros::Duration(0, 0)) const;
  bool isServerConnected() const;
  void sendGoal(const Goal & goal, SimpleDoneCallback done_cb = SimpleDoneCallback(),
                SimpleActiveCallback active_cb = SimpleActiveCallback(),
                SimpleFeedbackCallback feedback_cb = SimpleFeedbackCallback());
  SimpleClientGoalState sendGoalAndWait(const Goal & goal, const ros::Duration & execute_timeout = ros::Duration(0, 0),
                                        const ros::Duration & preempt_timeout = ros::Duration(0, 0));
  bool waitForResult(const ros::Duration & timeout = ros::Duration(0, 0));
  ResultConstPtr getResult() const;
  SimpleClientGoalState getState() const;
  void cancelAllGoals();
  void cancelGoalsAtAndBeforeTime(const ros::Time & time);
  void cancelGoal();
  void stopTrackingGoal();
};
}  // namespace actionlib
#endif
