"""rclpy.qos as a generated test uses it: a profile of settable policies and the policy values."""

import enum


class ReliabilityPolicy(enum.Enum):
    RELIABLE = 1
    BEST_EFFORT = 2


class DurabilityPolicy(enum.Enum):
    TRANSIENT_LOCAL = 1
    VOLATILE = 2


class LivelinessPolicy(enum.Enum):
    AUTOMATIC = 1
    MANUAL_BY_TOPIC = 3


class QoSProfile:
    def __init__(self, *, depth, reliability=ReliabilityPolicy.RELIABLE):
        self.depth, self.reliability = depth, reliability
        self.durability, self.liveliness = DurabilityPolicy.VOLATILE, LivelinessPolicy.AUTOMATIC
        self.deadline = self.liveliness_lease_duration = None
