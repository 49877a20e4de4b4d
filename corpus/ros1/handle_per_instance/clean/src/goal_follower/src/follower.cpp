// Follows poses: each GoalFollower turns the poses it hears on "pose" into goals on "goal",
// relative to the handle it is given. The node makes one on its global handle (/pose, /goal)
// and one on its private handle (~pose, ~goal).
#include <geometry_msgs/PoseStamped.h>
#include <ros/ros.h>

class GoalFollower {
public:
  explicit GoalFollower(ros::NodeHandle nh) {
    goal_ = nh.advertise<geometry_msgs::PoseStamped>("goal", 1);
    pose_ = nh.subscribe("pose", 1, &GoalFollower::onPose, this);
  }

private:
  void onPose(const geometry_msgs::PoseStamped::ConstPtr& pose) {
    geometry_msgs::PoseStamped goal = *pose;
    goal.pose.position.x += 1.0;
    goal_.publish(goal);
  }

  ros::Publisher goal_;
  ros::Subscriber pose_;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "follower");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  GoalFollower world(nh);
  GoalFollower local(pnh);
  ros::spin();
  return 0;
}
