"""The part of rclpy a generated test uses: a context, init with a domain, a node with publishers
(which keep what they publish, the stand-in has no transport), subscriptions and a clock."""

import time

from .context import Context  # rclpy exports it


def init(*, context=None, domain_id=None):
    (context or Context()).domain_id = domain_id


class _Time:
    def __init__(self):
        self.nanoseconds = time.time_ns()


class _Clock:
    def now(self):
        return _Time()


class Publisher:
    def __init__(self, msg_type, topic):
        self.msg_type, self.topic, self.published = msg_type, topic, []

    def publish(self, msg):
        assert isinstance(msg, self.msg_type), f"{type(msg).__name__} published on a {self.msg_type.__name__} topic"
        self.published.append(msg)

    def get_subscription_count(self):
        return 0


class Node:
    def __init__(self, name, *, context=None):
        self.name, self.context = name, context
        self.publishers, self.subscriptions = {}, {}

    def create_publisher(self, msg_type, topic, qos):
        self.publishers[topic] = Publisher(msg_type, topic)
        return self.publishers[topic]

    def create_subscription(self, msg_type, topic, callback, qos):
        self.subscriptions[topic] = (msg_type, callback)

    def get_clock(self):
        return _Clock()

    def count_publishers(self, topic):
        return 0

    def get_node_names_and_namespaces(self):
        return [(self.name, "/")]

    def destroy_node(self):
        self.publishers, self.subscriptions = {}, {}


def create_node(name, *, context=None):
    return Node(name, context=context)
