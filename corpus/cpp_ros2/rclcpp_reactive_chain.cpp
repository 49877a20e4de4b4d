// A safety filter between a teleop and the base: commands go through a chain of helpers to a
// publisher handed over as an argument; the virtual limit() of the base filter is overridden; a
// stop is sent from a free function given the publisher; the main loop spins at 50 Hz and
// publishes the filter state once the first command has arrived (a flag a callback sets).
#include <memory>

#include "geometry_msgs/msg/twist.hpp"
#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/bool.hpp"
#include "std_msgs/msg/string.hpp"

using Twist = geometry_msgs::msg::Twist;

void send_stop(const rclcpp::Publisher<Twist>::SharedPtr & pub)
{
  pub->publish(Twist());
}

class FilterNode : public rclcpp::Node
{
public:
  FilterNode()
  : Node("safety_filter")
  {
    out_pub_ = create_publisher<Twist>("cmd_vel_safe", 10);
    state_pub_ = create_publisher<std_msgs::msg::String>("~/state", 1);
    cmd_sub_ = create_subscription<Twist>(
      "cmd_vel", 10, [this](Twist::SharedPtr cmd) {on_command(*cmd);});
    estop_sub_ = create_subscription<std_msgs::msg::Bool>(
      "estop", 1, [this](std_msgs::msg::Bool::SharedPtr msg) {
        if (msg->data) {
          send_stop(out_pub_);
        }
      });
  }

  void report()
  {
    if (!commanded_) {
      return;
    }
    std_msgs::msg::String state;
    state.data = "filtering";
    state_pub_->publish(state);
  }

protected:
  virtual double limit(double speed) const {return speed;}

private:
  void on_command(const Twist & cmd)
  {
    commanded_ = true;
    forward(cmd, out_pub_);
  }

  void forward(Twist cmd, const rclcpp::Publisher<Twist>::SharedPtr & pub)
  {
    cmd.linear.x = limit(cmd.linear.x);
    pub->publish(cmd);
  }

  rclcpp::Publisher<Twist>::SharedPtr out_pub_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr state_pub_;
  rclcpp::Subscription<Twist>::SharedPtr cmd_sub_;
  rclcpp::Subscription<std_msgs::msg::Bool>::SharedPtr estop_sub_;
  bool commanded_{false};
};

class SlowFilterNode : public FilterNode
{
protected:
  double limit(double speed) const override {return speed > 0.3 ? 0.3 : speed;}
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<SlowFilterNode>();
  rclcpp::Rate rate(50.0);
  while (rclcpp::ok()) {
    rclcpp::spin_some(node);
    node->report();
    rate.sleep();
  }
  rclcpp::shutdown();
  return 0;
}
