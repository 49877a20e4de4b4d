// The other nodelet of the library, in a file that includes SSE intrinsics (as Eigen and PCL do).
// clang's builtin headers are those of the installed clang, which libclang may be newer than:
// their errors are not the code's, so this file is read from its syntax tree, only for the
// exported class's code (there is none here), and its own ports are not read from the tokens.
#include <emmintrin.h>
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>
#include <ros/ros.h>
#include <std_msgs/Float32.h>

namespace sums
{
class SumNodelet : public nodelet::Nodelet
{
  ros::Publisher pub_;

  void onInit() override
  {
    ros::NodeHandle& nh = getPrivateNodeHandle();
    pub_ = nh.advertise<std_msgs::Float32>("sum", 1);
  }

public:
  static float add(float a, float b)
  {
    __m128 x = _mm_set1_ps(a);
    __m128i bytes = _mm_adds_epi8(_mm_castps_si128(x), _mm_castps_si128(_mm_set1_ps(b)));
    return _mm_cvtss_f32(_mm_add_ps(x, _mm_castsi128_ps(bytes)));
  }
};
}  // namespace sums

PLUGINLIB_EXPORT_CLASS(sums::SumNodelet, nodelet::Nodelet)
