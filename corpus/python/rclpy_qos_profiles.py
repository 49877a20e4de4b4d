"""rclpy: a watchdog with the QoS forms rclpy offers: policy enums (old and new names),
durations, profiles changed attribute by attribute, and preset profiles."""
import copy

import rclpy
import rclpy.duration
from rclpy.duration import Duration
from rclpy.node import Node
from rclpy.qos import (DurabilityPolicy, LivelinessPolicy, QoSDurabilityPolicy, QoSPresetProfiles, QoSProfile,
                       QoSReliabilityPolicy, qos_profile_sensor_data, qos_profile_system_default)
from std_msgs.msg import Bool, Header, UInt32

HEARTBEAT_DEPTH = 3


class Watchdog(Node):

    def __init__(self):
        super().__init__('watchdog')
        timeout = self.declare_parameter('timeout', 0.5).value
        self.get_parameter_or('strict', True)

        strict = QoSProfile(
            depth=HEARTBEAT_DEPTH,
            reliability=QoSReliabilityPolicy.RELIABLE,
            deadline=Duration(seconds=0, nanoseconds=200_000_000),
            liveliness=LivelinessPolicy.MANUAL_BY_TOPIC,
            liveliness_lease_duration=rclpy.duration.Duration(seconds=1, nanoseconds=500_000_000),
        )
        self.beat_sub = self.create_subscription(UInt32, 'heartbeat', self.on_beat, strict)

        latched = QoSProfile(depth=1)
        latched.durability = DurabilityPolicy.TRANSIENT_LOCAL
        latched.lifespan = Duration(seconds=30)
        self.alarm_pub = self.create_publisher(Bool, 'alarm', latched)

        legacy = QoSProfile(depth=5, durability=QoSDurabilityPolicy.RMW_QOS_POLICY_DURABILITY_VOLATILE)
        self.stamp_pub = self.create_publisher(Header, 'stamps', legacy)

        shallow = copy.copy(qos_profile_sensor_data)
        shallow.depth = 1
        self.create_subscription(UInt32, 'raw_beat', self.on_beat, shallow)
        self.create_subscription(UInt32, 'beat_default', self.on_beat, qos_profile_system_default)
        self.create_subscription(UInt32, 'beat_preset', self.on_beat, QoSPresetProfiles.SENSOR_DATA.value)
        self.create_subscription(UInt32, 'beat_short', self.on_beat,
                                 QoSPresetProfiles.get_from_short_key('services_default'))
        self.create_subscription(UInt32, 'beat_computed', self.on_beat, self.pick_profile())
        self.feed_pub = self.make_feed('feed', QoSProfile(depth=2))

        flaky = QoSProfile(depth=4)
        if self.get_parameter('strict').value:
            flaky.reliability = QoSReliabilityPolicy.BEST_EFFORT
        self.flaky_pub = self.create_publisher(UInt32, 'flaky', flaky)
        self.timer = self.create_timer(timeout, self.check)
        self.last = None

    def make_feed(self, topic, profile):
        return self.create_publisher(UInt32, topic, profile)

    def pick_profile(self):
        return qos_profile_sensor_data if self.get_parameter('strict').value else qos_profile_system_default

    def on_beat(self, msg):
        self.last = msg.data

    def check(self):
        self.alarm_pub.publish(Bool(data=self.last is None))


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Watchdog())
    rclpy.shutdown()


if __name__ == '__main__':
    main()
