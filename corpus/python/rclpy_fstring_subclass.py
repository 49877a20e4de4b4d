"""rclpy: a Node subclass initialised with keywords, topics built with f-strings."""
import rclpy
from rclpy.node import Node
from sensor_msgs.msg import JointState
from std_msgs.msg import Float64

WHEEL_NS = 'wheels'


class WheelMonitor(Node):
    SIDE = 'left'

    def __init__(self):
        super().__init__(node_name='wheel_monitor', namespace='base')
        self.joint = f'{self.SIDE}_wheel_joint'
        self.speed_pub = self.create_publisher(Float64, f'{WHEEL_NS}/{self.SIDE}/speed', 10)
        self.state_sub = self.create_subscription(
            JointState, f'/{WHEEL_NS}/joint_states', self.on_state, 10)
        self.debug_pub = self.create_publisher(Float64, f'~/{self.joint}/raw', 1)

    def on_state(self, msg):
        if self.joint in msg.name:
            index = msg.name.index(self.joint)
            self.speed_pub.publish(Float64(data=msg.velocity[index]))
            self.debug_pub.publish(Float64(data=msg.position[index]))


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(WheelMonitor())
    rclpy.shutdown()


if __name__ == '__main__':
    main()
