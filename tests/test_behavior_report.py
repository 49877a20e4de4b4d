"""`archlog behavior`: each node's state machine from the behavior facts and derived relations."""

from __future__ import annotations

import io
from pathlib import Path

from rich.console import Console

from archlog.config import Config
from archlog.queries.rule_tests import load_facts
from archlog.queries.session import Session
from archlog.reports.behavior import behavior_model, print_behavior
from archlog.rules.ruleset import load_rules

CASE = Path(__file__).resolve().parent.parent / "archlog/rules/builtin/tests/AL601_required_input_unreachable"


def model() -> list[dict]:
    store = load_facts(CASE / "facts.json")
    return behavior_model(store, Session(store, load_rules([]), Config()).ctl)


def test_model_has_triggers_guards_state_and_required_inputs() -> None:
    nodes = {n["node"]: n for n in model()}
    assert sorted(nodes) == ["/base", "/follower", "/lattice", "/mapper"]
    [trajectory] = nodes["/lattice"]["outputs"]
    assert (trajectory["name"], trajectory["file"], trajectory["line"]) == ("/trajectory", "lattice.cpp", 21)
    assert trajectory["requires"] == ["/odom_pose"]
    [call] = trajectory["calls"]
    assert call["triggers"] == [{"kind": "timer", "by": "0.1 s", "file": "", "line": 0}]
    assert call["guards"] == [{"var": "has_pose_", "value": "true", "file": "lattice.cpp", "line": 38}]
    assert nodes["/lattice"]["state"] == [{"var": "has_pose_", "initial": "false", "set_by": [
        {"value": "true", "by": "/odom_pose", "file": "lattice.cpp", "line": 30}]}]
    assert nodes["/follower"]["outputs"][0]["requires"] == ["/trajectory"]
    assert nodes["/base"]["outputs"][0]["requires"] == []


def test_text_shows_the_state_machine() -> None:
    out = io.StringIO()
    print_behavior(model(), Console(file=out, width=200, no_color=True))
    text = out.getvalue()
    assert "state has_pose_ = false; on /odom_pose: true (lattice.cpp:30)" in text
    assert "publishes at lattice.cpp:40 on a timer every 0.1 s when has_pose_=true" in text
    assert "publishes at follower.py:15 when /trajectory arrives" in text
    assert "requires /odom_pose" in text
