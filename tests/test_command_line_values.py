"""Values a Python node takes from its command line (argparse), bound per node instance to the
words its launch file gives it (corpus/ros2/argparse_topic_name runs the same nodes for real)."""

from __future__ import annotations

import pytest
from conftest import CORPUS_ROS2, run_case

from archlog.system.command_line import command_value, command_word
from archlog.values import CommandArg, Concat, Switch

SENSOR = CommandArg(1, (), "front", ("--rate",))
RATE = CommandArg(0, ("--rate", "-r"), "10.0", ("--rate", "-r"))
FILTERED = CommandArg(0, ("--filtered",), "false", ("--rate", "-r"), present="true")


@pytest.mark.parametrize(("arg", "line", "word"), [
    (SENSOR, "", None), (SENSOR, "rear", "rear"), (SENSOR, "--rate 5 rear", "rear"), (SENSOR, "--filtered rear", "rear"),
    (SENSOR, "a:=b rear", "rear"), (RATE, "rear --rate 5", "5"), (RATE, "--rate=5 -r 7", "7"), (RATE, "rear", None),
    (FILTERED, "rear --filtered", "true"), (FILTERED, "rear", None), (SENSOR, "'unclosed", None)])
def test_the_word_a_command_line_gives_an_argument(arg: CommandArg, line: str, word: str | None) -> None:
    assert command_word(arg, line) == word


def test_a_name_built_from_arguments_and_a_flag_test() -> None:
    topic = Concat((SENSOR, Switch(FILTERED, "true", "/range_filtered", "/range")))
    assert command_value(topic, "") == "front/range"
    assert command_value(topic, "rear --filtered --rate 3") == "rear/range_filtered"


def test_each_instance_is_named_and_publishes_as_its_arguments_say() -> None:
    analysis, findings = run_case(CORPUS_ROS2 / "argparse_topic_name" / "clean")
    assert findings == []
    publishers = {(str(node), str(topic)) for _p, node, topic, _t in analysis.store.rows("publisher")
                  if str(node).endswith("_ranger") and not str(topic).startswith(("/rosout", "/parameter_events"))}
    assert publishers == {("/front_ranger", "/front/range_filtered"), ("/rear_ranger", "/rear/range")}
