"""The ROS 2 QoS vocabulary shared by the rclpy (python/qos_profile.py) and rclcpp (cpp/rclcpp/qos.py) readers.

A `Qos` starts from a preset (rmw's profiles, as rclcpp's QoS classes and rclpy's qos_profile_*
name them) or from a depth, and changes one policy at a time, the way rclcpp's builder methods
and rclpy's QoSProfile attributes do. `facts()` is what a port records: history and depth (for
keep_last), reliability and durability always when known, deadline, lifespan, liveliness and
lease duration only when they differ from the default (an absent duration is infinite), and
`profile`: the preset's name, or `?(expr)` when part of the QoS could not be read.
Values are lowercase snake case; durations are decimal seconds ("0.1").
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from fractions import Fraction

POLICIES = ("profile", "history", "depth", "reliability", "durability", "deadline", "lifespan", "liveliness",
            "liveliness_lease_duration")
DURATIONS = ("deadline", "lifespan", "liveliness_lease_duration")
VALUES = {
    "history": ("keep_last", "keep_all", "system_default", "unknown"),
    "reliability": ("reliable", "best_effort", "system_default", "best_available", "unknown"),
    "durability": ("volatile", "transient_local", "system_default", "best_available", "unknown"),
    "liveliness": ("automatic", "manual_by_node", "manual_by_topic", "system_default", "best_available", "unknown"),
}
# rmw_qos_profile_default: what a bare depth gets (rclcpp::QoS(10), rclpy's QoSProfile(depth=10))
DEFAULT = {"history": "keep_last", "depth": "10", "reliability": "reliable", "durability": "volatile",
           "liveliness": "system_default"}
# rmw's and rcl's profiles (rmw/qos_profiles.h, rcl/logging_rosout.h, rcl_action/default_qos.h) and
# rclcpp's ClockQoS (KeepLast(1) over the sensor-data profile); durations absent are infinite
PRESETS: dict[str, dict[str, str]] = {
    "default": DEFAULT,
    "sensor_data": {**DEFAULT, "depth": "5", "reliability": "best_effort"},
    "parameters": {**DEFAULT, "depth": "1000"},
    "services_default": DEFAULT,
    "parameter_events": {**DEFAULT, "depth": "1000"},
    "system_default": {"history": "system_default", "depth": "0", "reliability": "system_default",
                       "durability": "system_default", "liveliness": "system_default"},
    "best_available": {**DEFAULT, "reliability": "best_available", "durability": "best_available",
                       "liveliness": "best_available"},
    "unknown": {"history": "unknown", "depth": "0", "reliability": "unknown", "durability": "unknown",
                "liveliness": "unknown"},
    "rosout_default": {**DEFAULT, "depth": "1000", "durability": "transient_local", "lifespan": "10"},
    "action_status_default": {**DEFAULT, "depth": "1", "durability": "transient_local"},
    "clock": {**DEFAULT, "depth": "1", "reliability": "best_effort"},
}
# how the three APIs spell the presets: rclcpp classes, rmw/rcl C profiles, rclpy module constants
PRESET_NAMES = {
    "QoS": "default", "SensorDataQoS": "sensor_data", "ParametersQoS": "parameters",
    "ServicesQoS": "services_default", "ParameterEventsQoS": "parameter_events", "RosoutQoS": "rosout_default",
    "SystemDefaultsQoS": "system_default", "BestAvailableQoS": "best_available", "ClockQoS": "clock",
    "rcl_qos_profile_rosout_default": "rosout_default",
    "rcl_action_qos_profile_status_default": "action_status_default",
    **{f"rmw_qos_profile_{name}": name for name in ("default", "sensor_data", "parameters", "services_default",
                                                     "parameter_events", "system_default", "best_available",
                                                     "unknown")},
    **{f"qos_profile_{name}": name for name in ("sensor_data", "parameters", "services_default", "parameter_events",
                                                 "system_default", "unknown", "action_status_default")},
}
# builder methods without an argument: rclcpp::QoS().reliable() ...
FIXED_SETTERS = {
    "reliable": ("reliability", "reliable"), "best_effort": ("reliability", "best_effort"),
    "reliability_best_available": ("reliability", "best_available"),
    "durability_volatile": ("durability", "volatile"), "transient_local": ("durability", "transient_local"),
    "durability_best_available": ("durability", "best_available"), "keep_all": ("history", "keep_all"),
}
_INFINITE = Fraction(9223372036)  # rmw's RMW_DURATION_INFINITE is 9223372036 s 854775807 ns


def preset_name(spelling: str) -> str | None:
    """The preset a name denotes: `rclcpp::SensorDataQoS`, `rmw_qos_profile_sensor_data`,
    `rclpy.qos.qos_profile_sensor_data`, `QoSPresetProfiles.SENSOR_DATA` -> "sensor_data"."""
    last = re.split(r"::|\.", spelling.strip())
    if len(last) >= 2 and last[-2] == "QoSPresetProfiles" and last[-1].lower() in PRESETS:
        return last[-1].lower()
    if last[-1] == "value" and len(last) >= 3 and last[-3] == "QoSPresetProfiles":
        return preset_name(".".join(last[:-1]))
    return PRESET_NAMES.get(last[-1])


def policy_value(policy: str, spelling: str) -> str | None:
    """A policy value in archlog's vocabulary from any of its spellings:
    `rclcpp::ReliabilityPolicy::BestEffort`, `RMW_QOS_POLICY_RELIABILITY_BEST_EFFORT`,
    `QoSReliabilityPolicy.RMW_QOS_POLICY_RELIABILITY_BEST_EFFORT`, `ReliabilityPolicy.BEST_EFFORT`."""
    word = re.split(r"::|\.", spelling.strip())[-1]
    word = re.sub(rf"^RMW_QOS_POLICY_{policy.upper()}_", "", word)
    snake = re.sub(r"(?<=[a-z0-9])(?=[A-Z])", "_", word).lower()
    return snake if snake in VALUES.get(policy, ()) else None


def seconds_text(seconds: Fraction) -> str:
    """Decimal seconds ("0.1", "2"); "" for 0 or infinite (both mean: no such constraint)."""
    if seconds <= 0 or seconds >= _INFINITE:
        return ""
    nanoseconds = round(seconds * 1_000_000_000)
    whole, fraction = divmod(nanoseconds, 1_000_000_000)
    return f"{whole}.{fraction:09d}".rstrip("0").rstrip(".") if fraction else str(whole)


def number(text: str) -> Fraction | None:
    """A numeric literal as written in C++ or Python (`10`, `0.5`, `1e-3`, `100u`, `2.0f`)."""
    match = re.fullmatch(r"\s*([+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)(?:[uUlLfF]*)\s*", text.replace("'", ""))
    if match is None:
        return None
    try:
        return Fraction(match.group(1))
    except (ValueError, ZeroDivisionError):
        return None


@dataclass
class Qos:
    """A QoS profile being read: known policy values, its preset, and what could not be read."""

    policies: dict[str, str] = field(default_factory=lambda: dict(DEFAULT))
    profile: str = ""
    unread: list[str] = field(default_factory=list)

    @classmethod
    def preset(cls, name: str) -> Qos:
        return cls(dict(PRESETS[name]), "" if name == "default" else name)

    @classmethod
    def unknown(cls, expr: str) -> Qos:
        return cls({}, "", [expr])

    def copy(self) -> Qos:
        return Qos(dict(self.policies), self.profile, list(self.unread))

    def initialise(self, history: str | None, depth: str | None, expr: str) -> None:
        """rclcpp's QoSInitialization (KeepLast(n), KeepAll(), from_rmw(p)): history and depth
        (which only keep_last has)."""
        self.set("history", history, expr)
        if history == "keep_last" or history is None:
            self.set("depth", depth, expr)
        else:
            self.policies.pop("depth", None)

    def set(self, policy: str, value: str | None, expr: str) -> None:
        """Set a policy from a value already in archlog's vocabulary; None: not readable."""
        if value is None:
            self.policies.pop(policy, None)
            self.unread.append(expr)
        else:
            self.policies[policy] = value

    def apply(self, method: str, argument: str | None, expr: str) -> bool:
        """One builder method or attribute; `argument` is the value as written (an enum spelling,
        a depth) or, for durations, decimal seconds ("" for none); None when it is not readable.
        False when `method` is not a QoS setter."""
        if method in FIXED_SETTERS:
            self.set(*FIXED_SETTERS[method], expr)
        elif method == "keep_last":
            self.initialise("keep_last", argument, expr)
        elif method == "depth" or method in DURATIONS:
            self.set(method, argument, expr)
        elif method in VALUES:
            self.set(method, policy_value(method, argument) if argument is not None else None, expr)
        else:
            return False
        return True

    def facts(self) -> tuple[tuple[str, str], ...]:
        """(policy, value) pairs in POLICIES order, as a port records them."""
        known = self.policies
        out: dict[str, str] = {}
        if self.unread:
            out["profile"] = f"?({self.unread[0]})"
        elif self.profile:
            out["profile"] = self.profile
        for policy in POLICIES[1:]:
            value = known.get(policy)
            if not value or (policy == "depth" and known.get("history") != "keep_last") or \
                    (policy == "liveliness" and value == "system_default"):
                continue
            out[policy] = value
        return tuple(out.items())
