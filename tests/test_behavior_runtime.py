"""Runtime check of the behavior classification (issue 9): each corpus/behavior system is built
(roscpp nodes with g++) and launched with Debian's roslaunch on a loopback master with its required
input disconnected (the buggy variant). A rospy subscriber counts the messages on every output:
outputs classified as requiring the missing input (directly or through silenced nodes) must stay
silent for several seconds while the others publish; then the input is fed with `rostopic pub` and
the held outputs must start. The clean twin, launched as is, publishes every output.

Each observation is checked against the expected model of the case (the corpus tells the truth)
and against the model archlog recovers (the classification is right)."""

from __future__ import annotations

import functools
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, replace
from pathlib import Path

import pytest
from conftest import CORPUS_BEHAVIOR, corpus_cases, load_case, requires_ros, run_case
from support.behavior import Key, Model, Output, analysis_behavior, case_dir, expected_behavior, silenced_outputs
from support.build_cpp import build_workspace
from support.live_graph import live_system

from archlog.analysis import resolve_launch
from archlog.diagnostics import DiagnosticSink
from archlog.extract.workspace.index import Workspace
from archlog.observe import Architecture, compare, from_facts

pytestmark = requires_ros()

CASES = [v for v in corpus_cases(CORPUS_BEHAVIOR) if load_case(v).get("runtime")]
BUGGY = [v for v in CASES if v.name == "buggy"]
CLEAN = [v for v in CASES if v.name == "clean"]

SILENCE = 5.0  # seconds the held outputs must stay silent while free ones publish
START = 10.0  # seconds the held outputs get to start once the input is fed (rostopic needs ~1 s)
CONNECT = 10.0  # seconds the monitor waits for a publisher connection on every output


@dataclass(frozen=True)
class Observation:
    before: dict[str, int]  # messages per output topic, input disconnected (SILENCE seconds)
    after: dict[str, int]  # new messages per output topic once the input is fed (buggy only)
    unconnected: tuple[str, ...]  # outputs the monitor found no publisher for
    live: Architecture
    recovered: Architecture
    phases: tuple[tuple[str, float], ...]  # seconds from the start at the end of each phase


@functools.cache
def _models(variant: Path) -> tuple[Model, Model, Architecture]:
    analysis, _findings = run_case(variant)
    return expected_behavior(load_case(variant)), analysis_behavior(analysis), from_facts(analysis.store)


def observe(variant: Path) -> Observation:
    """The observation of one variant; a system's two variants are observed together, each on its
    own master (twice as fast, and they cannot hear each other)."""
    outcome = _observe_system(variant.parent)[variant.name]
    if isinstance(outcome, Exception):
        raise outcome
    return outcome


@functools.cache
def _observe_system(system: Path) -> dict[str, Observation | Exception]:
    variants = sorted(v for v in CASES if v.parent == system)
    for variant in variants:  # analysed here, one after the other: clingo is not safe to call from two threads
        _models(variant)
    with ThreadPoolExecutor(max_workers=len(variants)) as pool:
        futures = {v.name: pool.submit(_observe, v) for v in variants}
    return {name: future.exception() or future.result() for name, future in futures.items()}


def _observe(variant: Path) -> Observation:
    """Launch the system, count messages per output while the input is missing, then while it is
    fed (buggy variants); everything started is stopped before returning."""
    start = time.monotonic()
    phases: list[tuple[str, float]] = []
    case = load_case(variant)
    expected, recovered, architecture = _models(variant)
    phases.append(("analysed", time.monotonic() - start))
    topics = sorted({k[1] for k in expected} | {k[1] for k in recovered})
    feed = case.get("feed")
    after: dict[str, int] = {}
    with tempfile.TemporaryDirectory() as tmp:
        src = build_workspace(variant, Path(tmp) / "ws")
        files = [resolve_launch(spec, Workspace([src.parent], DiagnosticSink())) for spec in case["launch"]]
        phases.append(("built", time.monotonic() - start))
        with live_system(src, files, case.get("args", {}), expect_nodes=len(architecture.nodes), settle=1.0,
                         timeout=60) as system:
            phases.append(("launched", time.monotonic() - start))
            monitor = system.monitor(topics, connect_timeout=CONNECT)
            monitor.wait_ready(CONNECT + 10)
            phases.append(("connected", time.monotonic() - start))
            if feed is None:  # clean twin: wait until every output that requires an input has published
                needed = {k[1] for model in (expected, recovered) for k, out in model.items() if out.requires}
                before = monitor.wait_until(lambda c: all(c[t] for t in needed), SILENCE + START)
                phases.append(("all published", time.monotonic() - start))
            else:
                time.sleep(SILENCE)
                before = monitor.counts()
                phases.append(("silence", time.monotonic() - start))
                system.publish(feed["topic"], feed["type"], feed["message"])
                held = [t for t in topics if not before[t]]
                counts = monitor.wait_until(lambda c: all(c[t] for t in held), START)
                after = {t: counts[t] - before[t] for t in topics}
                phases.append(("fed", time.monotonic() - start))
            unconnected, graph = tuple(monitor.unconnected), system.graph
    phases.append(("stopped", time.monotonic() - start))
    return Observation(before, after, unconnected, graph, architecture, tuple(phases))


def _check_buggy(model: Model, feed: str, seen: Observation) -> list[tuple[Key, str]]:
    """What the observation contradicts in a model's classification of the buggy system."""
    held = silenced_outputs(model)
    problems = []
    for key in sorted(model):
        topic = key[1]
        if key in held and seen.before[topic]:
            problems.append((key, f"classified as requiring {sorted(model[key].requires)} but published "
                                  f"{seen.before[topic]} messages while {feed} was not"))
        if key not in held and not seen.before[topic]:
            problems.append((key, f"classified as free but silent for {SILENCE} s without {feed}"))
        if key in held and not seen.after[topic]:
            problems.append((key, f"did not start within {START} s of feeding {feed}"))
    return problems


@pytest.mark.parametrize("variant", BUGGY, ids=case_dir)
def test_expected_model_holds_at_runtime(variant: Path) -> None:
    """The corpus's behavior model is true: the outputs it says require the missing input are
    silent until the input is fed, the others publish."""
    seen = observe(variant)
    expected, _recovered, _arch = _models(variant)
    assert {k[1] for k in expected} & set(seen.unconnected) == set()
    assert _check_buggy(expected, load_case(variant)["feed"]["topic"], seen) == []


@pytest.mark.parametrize("variant", BUGGY, ids=case_dir)
def test_recovered_classification_holds_at_runtime(variant: Path) -> None:
    """archlog's classification is true: an output it says requires the missing input stays
    silent until the input is fed, an output it says requires nothing missing publishes."""
    seen = observe(variant)
    _expected, recovered, _arch = _models(variant)
    assert _check_buggy(recovered, load_case(variant)["feed"]["topic"], seen) == []


def test_runtime_check_rejects_wrong_classifications() -> None:
    """The check has teeth: on a real observation, a held output classified as free and a free
    output classified as requiring the missing input are both reported (and nothing else)."""
    variant = CORPUS_BEHAVIOR / "wait_first_pose" / "buggy"
    feed = load_case(variant)["feed"]["topic"]
    seen = observe(variant)
    expected, _recovered, _arch = _models(variant)
    held, free = ("/speed_profiler", "/speed_profile"), ("/vehicle_sim", "/odom")
    assert held in silenced_outputs(expected) and free in set(expected) - silenced_outputs(expected)
    wrong: dict[Key, Output] = dict(expected)
    wrong[held] = replace(expected[held], requires=frozenset())
    wrong[free] = replace(expected[free], requires=frozenset({feed}))
    problems = _check_buggy(wrong, feed, seen)
    assert sorted(key for key, _why in problems) == sorted([held, free]), problems


@pytest.mark.parametrize("variant", CLEAN, ids=case_dir)
def test_clean_twin_publishes_every_output_that_requires_an_input(variant: Path) -> None:
    """In the clean twin the inputs are delivered: every output classified as requiring one
    publishes (outputs that require nothing were seen publishing in the buggy twin; some of them
    only publish while an input is missing, a 'waiting for ...' status)."""
    seen = observe(variant)
    expected, recovered, _arch = _models(variant)
    assert {k[1] for k in expected} & set(seen.unconnected) == set()
    assert [k for k in sorted(expected) if expected[k].requires and not seen.before[k[1]]] == []
    assert [k for k in sorted(recovered) if recovered[k].requires and not seen.before[k[1]]] == []
    assert silenced_outputs(recovered) == set()


@pytest.mark.parametrize("variant", CASES, ids=case_dir)
def test_live_graph_equals_recovered_architecture(variant: Path) -> None:
    """The launched system's graph (read before the monitor joins) is the one archlog recovers."""
    seen = observe(variant)
    differences = {kind: (row["only_recovered"], row["only_observed"])
                   for kind, row in compare(seen.recovered, seen.live).items()}
    assert differences == {kind: ([], []) for kind in differences}

