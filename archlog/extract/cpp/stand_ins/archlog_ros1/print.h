// archlog stand-in: the log macros of archlog's ROS 1 stand-ins evaluate their arguments and
// print nothing. Written for archlog.
#ifndef ARCHLOG_ROS1_PRINT_H
#define ARCHLOG_ROS1_PRINT_H
#include <sstream>

namespace archlog_ros1
{
template<class... Args> void print(const Args &... args);
}  // namespace archlog_ros1

#define ARCHLOG_ROS_PRINT(...) ::archlog_ros1::print(__VA_ARGS__)
#define ARCHLOG_ROS_STREAM(args) do { std::stringstream archlog_stream; archlog_stream << args; } while (false)
#endif
