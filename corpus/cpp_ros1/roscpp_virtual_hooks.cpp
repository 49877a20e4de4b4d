// A sensor filter framework in one file: the base class subscribes and runs the virtual filter()
// from its callback; a derived filter overrides it and publishes only after calibration (a flag
// set by its own calibration callback through an overridden hook); the base's timer calls a
// pure virtual heartbeat, and a virtual callback registered through the base is overridden too.
#include <ros/ros.h>
#include <sensor_msgs/Imu.h>
#include <std_msgs/Bool.h>
#include <std_msgs/Empty.h>

class FilterBase
{
public:
  explicit FilterBase(ros::NodeHandle& nh)
  {
    imu_sub_ = nh.subscribe("imu", 10, &FilterBase::imuCallback, this);
    calib_sub_ = nh.subscribe("calibrated", 1, &FilterBase::onCalibration, this);
    beat_timer_ = nh.createTimer(ros::Duration(1.0), &FilterBase::beat, this);
  }
  virtual ~FilterBase() = default;

protected:
  virtual void filter(const sensor_msgs::Imu& imu) = 0;
  virtual void heartbeat() = 0;
  virtual void onCalibration(const std_msgs::Bool::ConstPtr& msg) { (void)msg; }
  virtual bool ready() const { return true; }

private:
  void imuCallback(const sensor_msgs::Imu::ConstPtr& imu)
  {
    if (!ready()) {
      return;
    }
    filter(*imu);
  }

  void beat(const ros::TimerEvent&) { heartbeat(); }

  ros::Subscriber imu_sub_;
  ros::Subscriber calib_sub_;
  ros::Timer beat_timer_;
};

class LowPassFilter : public FilterBase
{
public:
  explicit LowPassFilter(ros::NodeHandle& nh) : FilterBase(nh)
  {
    filtered_pub_ = nh.advertise<sensor_msgs::Imu>("imu_filtered", 10);
    alive_pub_ = nh.advertise<std_msgs::Empty>("filter_alive", 1);
  }

protected:
  void filter(const sensor_msgs::Imu& imu) override
  {
    state_.linear_acceleration.x = 0.9 * state_.linear_acceleration.x + 0.1 * imu.linear_acceleration.x;
    filtered_pub_.publish(state_);
  }

  void heartbeat() override { alive_pub_.publish(std_msgs::Empty()); }

  void onCalibration(const std_msgs::Bool::ConstPtr& msg) override { calibrated_ = msg->data; }

  bool ready() const override { return calibrated_; }

private:
  ros::Publisher filtered_pub_;
  ros::Publisher alive_pub_;
  sensor_msgs::Imu state_;
  bool calibrated_ = false;
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "imu_filter");
  ros::NodeHandle nh;
  LowPassFilter filter(nh);
  ros::spin();
  return 0;
}
