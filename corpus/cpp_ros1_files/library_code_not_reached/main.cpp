// The executable's own file: it builds a Sender (whose member is the library's Broadcaster) and a
// Reporter behind a Stage pointer, never a Listener, though the library it links defines one.
#include <memory>
#include "lib/kit.h"

class Sender
{
public:
  void send() { broadcaster_.send("ping"); }

private:
  kit::Broadcaster broadcaster_;
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "sender");
  ros::NodeHandle nh;
  Sender sender;
  std::unique_ptr<kit::Stage> stage(new kit::Reporter);
  stage->start(nh);
  sender.send();
  ros::spin();
}
