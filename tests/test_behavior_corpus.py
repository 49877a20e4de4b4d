"""Behavior (issue 9): every system of corpus/behavior yields its expected behavior model: for each
output of each node, the triggers of its publish calls (publish_trigger facts) and the topics it
requires (the derived relation required_topic); and AL601 names, at each root, the outputs it holds
back and the nodes silenced downstream. The findings themselves are checked by test_corpus.py."""

from __future__ import annotations

from pathlib import Path

import pytest
from conftest import CORPUS_BEHAVIOR, corpus_cases, load_case
from support.behavior import Key, Model, case_dir, describe, expected_behavior, recovered_behavior, silenced_outputs

from archlog.analysis import analyse
from archlog.extract.summary import TRIGGERS
from archlog.rules.engine import Engine, Finding, render
from archlog.rules.ruleset import load_rules

CASES = corpus_cases(CORPUS_BEHAVIOR)
BUGGY = [v for v in CASES if v.name == "buggy"]
ENGINE = Engine(load_rules([]))

# the patterns of issue 9, each in its own system, with the languages they are written in
PATTERNS = {"wait_first_pose": {"py", "cpp"}, "state_flag": {"py", "cpp"}, "timer_output": {"py", "cpp"},
            "reactive_pipeline": {"py", "cpp"}, "mode_switch": {"py", "cpp"}, "empty_checks": {"py", "cpp"},
            "virtual_methods": {"py", "cpp"}}


def _run(variant: Path) -> tuple[Model, list[Finding]]:
    case = load_case(variant)
    analysis = analyse([variant], case["launch"], case.get("args", {}), [variant / m for m in case.get("models", [])])
    ctl, findings = ENGINE.run(analysis.store)
    return recovered_behavior(analysis.store, ctl), findings


def test_every_pattern_has_a_system_with_rospy_and_roscpp_nodes() -> None:
    systems = {v.parent.name: v.parent for v in CASES}
    assert set(PATTERNS) <= set(systems)
    for name, languages in PATTERNS.items():
        for variant in ("buggy", "clean"):
            sources = {p.suffix.lstrip(".") for p in (systems[name] / variant / "src").rglob("*") if p.is_file()}
            assert languages <= sources, f"{name}/{variant} lacks {languages - sources} nodes"


@pytest.mark.parametrize("variant", CASES, ids=case_dir)
def test_expected_model_is_consistent(variant: Path) -> None:
    """The expected models themselves: known triggers, one publisher per output topic (the runtime
    check counts messages per topic); a buggy system silences some outputs, which all start when
    the missing input is fed; in a clean twin every output can be published."""
    case = load_case(variant)
    model = expected_behavior(case)
    assert model
    for out in model.values():
        assert out.triggers and out.triggers <= set(TRIGGERS) - {"unknown"}, out
        assert all(t.startswith("/") for t in {out.output, *out.requires}), out
    topics = [out.output for out in model.values()]
    assert len(topics) == len(set(topics)), "one publisher per output topic"
    if variant.name == "clean":
        assert silenced_outputs(model) == set()
        return
    feed = case["feed"]
    assert feed["topic"] not in topics, "the fed input must be one nothing in the system publishes"
    assert silenced_outputs(model) != set()
    assert silenced_outputs(model, frozenset({feed["topic"]})) == set()
    assert set(model) - silenced_outputs(model), "some output must publish without the input"
    assert {f["rule"] for f in case["findings"]} == {"AL601"}
    assert {f["subject"] for f in case["findings"]} == {feed["topic"]}


@pytest.mark.parametrize("variant", CASES, ids=case_dir)
def test_recovered_behavior_model(variant: Path) -> None:
    """Outputs, their triggers and required topics as archlog recovers them equal the expected model."""
    recovered, _findings = _run(variant)
    assert describe(recovered) == describe(expected_behavior(load_case(variant)))


def _root_lists(model: Model, node: str, topic: str) -> tuple[set[str], set[str]]:
    """What AL601 should list for the root `node` that requires `topic`: its outputs that require
    it, and the other nodes whose outputs are silenced through them (transitively)."""
    silenced = silenced_outputs(model)
    root: set[Key] = {k for k, out in model.items() if k[0] == node and topic in out.requires}
    held, frontier = set(root), set(root)
    while frontier:
        topics = {k[1] for k in frontier}
        frontier = {k for k, out in model.items() if k in silenced and out.requires & topics} - held
        held |= frontier
    return {k[1] for k in root}, {k[0] for k in held if k[0] != node}


@pytest.mark.parametrize("variant", BUGGY, ids=case_dir)
def test_unreachable_input_names_the_outputs_it_holds_and_the_nodes_it_silences(variant: Path) -> None:
    expected = expected_behavior(load_case(variant))
    _recovered, findings = _run(variant)
    roots = [f for f in findings if f.rule.id == "AL601"]
    assert roots, "no AL601 finding"
    for finding in roots:
        node, topic = render(finding.values["node"]), render(finding.values["topic"])
        outputs, silenced = _root_lists(expected, node, topic)
        assert finding.values["outputs"] == (", ".join(sorted(outputs)) or "none"), finding.message
        # an empty list leaves its part out of the message (issue 19)
        assert finding.values["silenced"] == \
            (f"; nodes silenced downstream: {', '.join(sorted(silenced))}" if silenced else ""), finding.message
