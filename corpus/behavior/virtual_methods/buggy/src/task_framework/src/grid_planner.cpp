// Grid planner: a periodic task that plans a straight grid path to the latest goal. The goal
// subscription lives in an intermediate base class that hands each goal to a virtual hook.
#include <cmath>

#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/PoseStamped.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>

#include "task_framework/periodic_task.h"

namespace task_framework {

class GoalTask : public PeriodicTask {
 public:
  GoalTask(ros::NodeHandle& nh, double period) : PeriodicTask(nh, period) {
    goal_sub_ = nh.subscribe("goal", 1, &GoalTask::goalCallback, this);
  }

 protected:
  virtual void onGoal(const geometry_msgs::PoseStamped& goal) = 0;

 private:
  void goalCallback(const geometry_msgs::PoseStamped::ConstPtr& msg) { onGoal(*msg); }

  ros::Subscriber goal_sub_;
};

class GridPlanner final : public GoalTask {
 public:
  explicit GridPlanner(ros::NodeHandle& nh) : GoalTask(nh, 0.25) {
    pnh_.param("cell_size", cell_size_, 0.5);
    plan_pub_ = nh.advertise<nav_msgs::Path>("grid_plan", 1);
    ack_pub_ = pnh_.advertise<geometry_msgs::PointStamped>("goal_ack", 1);
  }

 protected:
  void onGoal(const geometry_msgs::PoseStamped& goal) override {
    goal_ = goal;
    has_goal_ = true;
    geometry_msgs::PointStamped ack;
    ack.header = goal.header;
    ack.point = goal.pose.position;
    ack_pub_.publish(ack);
  }

  bool ready() const override { return has_goal_; }

  void step() override {
    nav_msgs::Path plan;
    plan.header.frame_id = goal_.header.frame_id;
    plan.header.stamp = ros::Time::now();
    const double dx = goal_.pose.position.x;
    const double dy = goal_.pose.position.y;
    const int cells = static_cast<int>(std::ceil(std::hypot(dx, dy) / cell_size_));
    for (int i = 0; i <= cells; ++i) {
      geometry_msgs::PoseStamped pose = goal_;
      const double f = cells == 0 ? 1.0 : static_cast<double>(i) / cells;
      pose.pose.position.x = std::round(f * dx / cell_size_) * cell_size_;
      pose.pose.position.y = std::round(f * dy / cell_size_) * cell_size_;
      plan.poses.push_back(pose);
    }
    plan_pub_.publish(plan);
  }

  std::string name() const override { return "grid_planner"; }

 private:
  ros::Publisher plan_pub_;
  ros::Publisher ack_pub_;
  geometry_msgs::PoseStamped goal_;
  bool has_goal_ = false;
  double cell_size_ = 0.5;
};

}  // namespace task_framework

int main(int argc, char** argv) {
  ros::init(argc, argv, "grid_planner");
  ros::NodeHandle nh;
  task_framework::GridPlanner planner(nh);
  ros::spin();
  return 0;
}
