// Front sonar of the forklift mast: simulated echo ranges published under /sensors, with the
// diagnostic self-test service the maintenance tools call.
#include <cmath>
#include <string>

#include <diagnostic_msgs/SelfTest.h>
#include <ros/ros.h>
#include <sensor_msgs/Range.h>

namespace {
ros::Publisher advertiseRange(ros::NodeHandle& nh, const std::string& transducer) {
  return nh.advertise<sensor_msgs::Range>(ros::names::append(transducer, "range"), 5);
}

bool selfTest(diagnostic_msgs::SelfTest::Request&, diagnostic_msgs::SelfTest::Response& res) {
  res.id = "sonar_front";
  res.passed = 1;
  diagnostic_msgs::DiagnosticStatus status;
  status.level = diagnostic_msgs::DiagnosticStatus::OK;
  status.name = "echo";
  status.message = "transducer answers";
  res.status.push_back(status);
  return true;
}
}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "sonar_array");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  ros::NodeHandle sensors(nh, "sensors");

  double rate;
  ros::param::param("~rate", rate, 10.0);
  double max_range;
  pnh.param("max_range", max_range, 4.0);

  ros::Publisher front_pub = advertiseRange(sensors, "sonar_front");
  ros::ServiceServer self_test = pnh.advertiseService("self_test", selfTest);

  sensor_msgs::Range range;
  range.header.frame_id = "sonar_front";
  range.radiation_type = sensor_msgs::Range::ULTRASOUND;
  range.field_of_view = 0.5;
  range.min_range = 0.05;
  range.max_range = static_cast<float>(max_range);

  ros::Rate loop(rate);
  double t = 0.0;
  while (ros::ok()) {
    range.header.stamp = ros::Time::now();
    range.range = static_cast<float>(1.5 + 1.2 * std::sin(0.5 * t));  // a pallet swinging past
    front_pub.publish(range);
    t += 1.0 / rate;
    ros::spinOnce();
    loop.sleep();
  }
  return 0;
}
