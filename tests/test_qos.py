"""The shared ROS 2 QoS vocabulary (archlog/extract/qos.py): presets as rmw defines them, value
spellings of rclcpp, rmw and rclpy, durations, and the facts a port records."""

from __future__ import annotations

from fractions import Fraction

import pytest

from archlog.extract.qos import PRESETS, Qos, number, policy_value, preset_name, seconds_text


def test_presets_match_rmw_and_rclcpp() -> None:
    assert Qos.preset("sensor_data").facts() == (
        ("profile", "sensor_data"), ("history", "keep_last"), ("depth", "5"), ("reliability", "best_effort"),
        ("durability", "volatile"))
    assert dict(Qos.preset("parameters").facts())["depth"] == "1000"
    assert dict(Qos.preset("parameter_events").facts())["depth"] == "1000"
    assert dict(Qos.preset("rosout_default").facts()) == {
        "profile": "rosout_default", "history": "keep_last", "depth": "1000", "reliability": "reliable",
        "durability": "transient_local", "lifespan": "10"}
    assert dict(Qos.preset("clock").facts()) == {"profile": "clock", "history": "keep_last", "depth": "1",
                                                 "reliability": "best_effort", "durability": "volatile"}
    assert dict(Qos.preset("action_status_default").facts())["durability"] == "transient_local"
    system = dict(Qos.preset("system_default").facts())
    assert system == {"profile": "system_default", "history": "system_default", "reliability": "system_default",
                      "durability": "system_default"}
    assert all(p["reliability"] and p["durability"] for p in PRESETS.values())


@pytest.mark.parametrize(("spelling", "preset"), [
    ("rclcpp::SensorDataQoS", "sensor_data"), ("SystemDefaultsQoS", "system_default"),
    ("rmw_qos_profile_services_default", "services_default"), ("rcl_qos_profile_rosout_default", "rosout_default"),
    ("rclpy.qos.qos_profile_sensor_data", "sensor_data"), ("qos_profile_action_status_default", "action_status_default"),
    ("QoSPresetProfiles.PARAMETERS", "parameters"), ("rclpy.qos.QoSPresetProfiles.SENSOR_DATA.value", "sensor_data"),
    ("rclcpp::QoS", "default"), ("my_profile", None),
])
def test_preset_names(spelling: str, preset: str | None) -> None:
    assert preset_name(spelling) == preset


@pytest.mark.parametrize(("policy", "spelling", "value"), [
    ("reliability", "rclcpp::ReliabilityPolicy::BestEffort", "best_effort"),
    ("reliability", "RMW_QOS_POLICY_RELIABILITY_RELIABLE", "reliable"),
    ("reliability", "rmw_qos_reliability_policy_e::RMW_QOS_POLICY_RELIABILITY_BEST_EFFORT", "best_effort"),
    ("reliability", "QoSReliabilityPolicy.RMW_QOS_POLICY_RELIABILITY_BEST_EFFORT", "best_effort"),
    ("durability", "DurabilityPolicy.TRANSIENT_LOCAL", "transient_local"),
    ("durability", "rclcpp::DurabilityPolicy::Volatile", "volatile"),
    ("history", "rclcpp::HistoryPolicy::KeepAll", "keep_all"),
    ("liveliness", "LivelinessPolicy.MANUAL_BY_TOPIC", "manual_by_topic"),
    ("liveliness", "rclcpp::LivelinessPolicy::ManualByTopic", "manual_by_topic"),
    ("reliability", "rclcpp::DurabilityPolicy::Volatile", None),
    ("reliability", "some_variable", None),
])
def test_policy_values(policy: str, spelling: str, value: str | None) -> None:
    assert policy_value(policy, spelling) == value


def test_durations_are_decimal_seconds_and_none_is_infinite() -> None:
    assert seconds_text(Fraction(1, 10)) == "0.1"
    assert seconds_text(Fraction(2)) == "2"
    assert seconds_text(Fraction(3, 2)) == "1.5"
    assert seconds_text(Fraction(1, 3)) == "0.333333333"
    assert seconds_text(Fraction(0)) == ""
    assert seconds_text(Fraction(9223372036) + Fraction(854775807, 10 ** 9)) == ""
    assert number("100u") == 100 and number("2.5f") == Fraction(5, 2) and number("1e-3") == Fraction(1, 1000)
    assert number("depth") is None


def test_builder_methods_and_unread_parts() -> None:
    qos = Qos.preset("default")
    qos.initialise("keep_last", "5", "KeepLast(5)")
    for method, argument in [("best_effort", None), ("transient_local", None), ("deadline", "0.1"),
                             ("liveliness", "rclcpp::LivelinessPolicy::ManualByTopic"),
                             ("liveliness_lease_duration", "2"), ("lifespan", "")]:
        assert qos.apply(method, argument, method)
    assert qos.facts() == (("history", "keep_last"), ("depth", "5"), ("reliability", "best_effort"),
                           ("durability", "transient_local"), ("deadline", "0.1"), ("liveliness", "manual_by_topic"),
                           ("liveliness_lease_duration", "2"))
    assert not qos.apply("avoid_ros_namespace_conventions", "true", "x")
    qos.apply("reliability", "reliability_from_a_parameter", ".reliability(p)")
    assert dict(qos.facts())["profile"] == "?(.reliability(p))" and "reliability" not in dict(qos.facts())
    keep_all = Qos.preset("default")
    keep_all.initialise("keep_all", None, "KeepAll()")
    assert keep_all.facts() == (("history", "keep_all"), ("reliability", "reliable"), ("durability", "volatile"))
    assert Qos.unknown("qos").facts() == (("profile", "?(qos)"),)
