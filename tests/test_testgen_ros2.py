"""Generated tests of the corpus/ros2 systems run for real on rclpy (issue 32): the nodes started
as plain processes (no ros2cli), typed parameters, test publishers offering the QoS the nodes ask
for, on a private domain. A correct system's generated test passes; a system with a node that is
not a Python node of its workspace (C++ without ros2cli here) is skipped with the reason. A node whose
only interface is a service gets calls with drawn requests, one whose only interface is an action
gets goals with drawn fields, and the line coverage of its file is in the report."""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
import time
from pathlib import Path

import pytest
from support.ros2_nodes import private_domain, rclpy_available
from support.testgen_corpus import prepare, run_generated

ROOT = Path(__file__).resolve().parents[1]
CORPUS = ROOT / "corpus" / "ros2"
SERVICE = ROOT / "corpus" / "testgen_ros2" / "service_division"  # a node whose only interface is a service
LIFECYCLE = ROOT / "corpus" / "testgen_ros2" / "lifecycle_scaler" / "clean"  # ports made in on_configure
ACTION = ROOT / "corpus" / "testgen_ros2" / "action_order"  # a node whose only interface is an action
# (system, nodes under test: all when empty, what the generated test does); each a clean twin
CASES = [("qos_deadline_watchdog", ["/base/watchdog"], "passed"), ("param_name_typo_py", [], "passed"),
         ("yaml_remap_near_miss", ["/robot1/smoother"], "passed"), ("qos_latched_map", [], "skipped")]

pytestmark = pytest.mark.skipif(not rclpy_available(), reason="rclpy (the ros2 extra) is not installed")


def _generate(system: str, nodes: list[str], out: Path) -> None:
    variant = CORPUS / system / "clean"
    case = json.loads((variant / "case.json").read_text())
    command = [sys.executable, "-m", "archlog", "testgen", str(variant), "--output", str(out)]
    command += [x for spec in case["launch"] for x in ("--launch", spec)]
    command += [x for node in nodes for x in ("--nodes", node)]
    subprocess.run(command, check=True, capture_output=True, text=True, timeout=120)


def run_case(system: str, nodes: list[str], tmp: Path, examples: int) -> tuple[subprocess.CompletedProcess, float]:
    """Generate the test of a clean twin into `tmp` and run it for `examples` examples on a private
    domain; the pytest run and its seconds."""
    _generate(system, nodes, tmp)
    domain = min(private_domain(), 232)  # Fast DDS computes no ports above 232
    env = dict(os.environ, ARCHLOG_TESTGEN_EXAMPLES=str(examples), ARCHLOG_TESTGEN_STEPS="4",
               ARCHLOG_TESTGEN_SHRINK_SECONDS="5", ARCHLOG_TESTGEN_DOMAINS=f"{domain}-{domain}")
    start = time.monotonic()
    result = subprocess.run([sys.executable, "-m", "pytest", "-q", "-rs", "-p", "no:cacheprovider", "-p", "no:xdist",
                             "--hypothesis-seed=0", str(tmp)], env=env, capture_output=True, text=True,
                            timeout=60 + 20 * examples, cwd=tmp)
    return result, time.monotonic() - start


@pytest.mark.parametrize(("system", "nodes", "outcome"), CASES, ids=[c[0] for c in CASES])
def test_generated_test_passes_a_correct_ros2_system(system: str, nodes: list[str], outcome: str, tmp_path: Path) -> None:
    result, _seconds = run_case(system, nodes, tmp_path, 3)
    if outcome == "skipped":  # a C++ node: pytest ran nothing (exit 5), saying why
        assert result.returncode == 5 and "cannot start" in result.stdout, result.stdout
    else:
        assert result.returncode == 0 and "1 passed" in result.stdout, result.stdout[-4000:] + result.stderr[-2000:]


def _twins(system: Path, tmp: Path, node: str, rule: str, examples: tuple[int, int], steps: int,
           shrink_seconds: int) -> list[dict]:
    """Generate and run both twins of a corpus/testgen_ros2 system (`examples`: the buggy one's search
    budget, the fixed one's run): the buggy one's test has the `rule`, fails with `node` dead, shrunk to
    at most 3 steps; the fixed one's passes, and the report has its node's line coverage (coverage.py
    in the node's process: some lines but not all). Returns the actions of the buggy one's replay."""
    out, _case = prepare(system / "buggy", tmp / "buggy")
    assert f"def {rule}(self, " in next(out.glob("test_*.py")).read_text()
    buggy = run_generated(out, examples[0], seed=0, shrink_seconds=shrink_seconds, steps=steps, timeout=300)
    assert not buggy.passed and buggy.replay is not None, buggy.output
    assert buggy.replay["reason"].startswith(f"node(s) died: {node}"), buggy.replay["reason"]
    assert 1 <= buggy.messages() <= 3, buggy.replay
    out, _case = prepare(system / "clean", tmp / "clean")
    clean = run_generated(out, examples[1], seed=0, steps=steps, timeout=300)
    assert clean.passed and clean.examples >= examples[1], clean.output
    covered = re.search(rf"{node} ran (\d+) of (\d+) lines", clean.output)
    assert covered and 0 < int(covered[1]) < int(covered[2]), clean.output
    return buggy.replay["actions"]


def test_a_service_under_test_gets_drawn_requests(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The planner dies on a zero tolerance (buggy twin): found, shrunk to at most 3 calls; its fixed
    twin answers every request (an empty plan for a tolerance that is not a positive length: the
    guard's early return and more run)."""
    domain = min(private_domain(), 232)
    monkeypatch.setenv("ARCHLOG_TESTGEN_DOMAINS", f"{domain}-{domain}")
    actions = _twins(SERVICE, tmp_path, "/planner", "call_plan_route", (12, 6), steps=5, shrink_seconds=8)
    calls = [a["request"] for a in actions if a["op"] == "call"]
    assert calls and str(calls[-1]["tolerance"]) in ("0.0", "-0.0", "nan"), calls  # the call that kills it


def test_an_action_under_test_gets_drawn_goals(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The sequencer's goal callback divides its time budget by the goal's order (buggy twin): found,
    shrunk to at most 3 goals, the last of order 0; its fixed twin rejects the orders it cannot serve
    and serves the others (a feedback per number, then the result)."""
    domain = min(private_domain(), 232)
    monkeypatch.setenv("ARCHLOG_TESTGEN_DOMAINS", f"{domain}-{domain}")
    actions = _twins(ACTION, tmp_path, "/sequencer", "send_goal_fibonacci", (4, 2), steps=3, shrink_seconds=3)
    goals = [a["goal"] for a in actions if a["op"] == "goal"]
    assert goals[-1] == {"order": 0}, goals


def test_a_lifecycle_node_is_activated_and_its_builtin_ports_left_out(tmp_path: Path,
                                                                      monkeypatch: pytest.MonkeyPatch) -> None:
    """The scaler makes its ports in on_configure: the test configures and activates it after every
    start (else its recovered ports are missing live), and its lifecycle services are not compared."""
    domain = min(private_domain(), 232)
    monkeypatch.setenv("ARCHLOG_TESTGEN_DOMAINS", f"{domain}-{domain}")
    out, _case = prepare(LIFECYCLE, tmp_path / "clean")
    outcome = run_generated(out, 4, seed=0, steps=4, timeout=300)
    assert outcome.passed and outcome.examples >= 4, outcome.output


PROMPT_NODE = """
import rclpy
from rclpy.node import Node


class Prompt(Node):
    def __init__(self):
        super().__init__("prompt")
        self.publisher = self.create_publisher(__import__("std_msgs.msg").msg.String, "said", 10)
        self.said = input("say something: ")  # blocks: nothing is typed


rclpy.init()
rclpy.spin(Prompt())
"""

PROMPT_DRIVER = """
import json, os, signal, sys, time
import rclpy
from archlog.testgen.ros2 import Ros2Session

model = {"commands": [{"name": "/prompt", "script": sys.argv[1], "remaps": [], "params": {}}], "nodes": ["/prompt"],
         "inputs": {}, "outputs": {}, "qos": {}}
session = Ros2Session(model, rclpy, {})
session.start()
seen = {"terminals": [], "down": []}
for _ in range(2):
    session.launch({})
    proc = session.procs["/prompt"]
    seen["terminals"].append([os.readlink(f"/proc/{proc.pid}/fd/0"), len(session.terminals)])
    end = time.monotonic() + 3.0
    while time.monotonic() < end:  # blocked in input() the whole time, and up
        seen["down"].append(session.down("/prompt"))
        time.sleep(0.2)
if sys.argv[2] == "kill":  # gone without a goodbye: its name stays discovered until the DDS lease ends
    os.kill(proc.pid, signal.SIGKILL)
    proc.wait(5)
    seen["killed"] = session.down("/prompt")
session.stop_nodes()
seen["held"] = len(session.terminals)
seen["listed"] = "/prompt" in session._names()
session.close()
print(json.dumps(seen))
"""


def _prompt(tmp_path: Path, how: str) -> dict:
    """Start a node blocked in input() twice in one session (`how`: "kill" SIGKILLs the second before
    the stop); what the driver saw."""
    node = tmp_path / "prompt.py"
    node.write_text(PROMPT_NODE)
    domain = min(private_domain(), 232)
    env = dict(os.environ, ARCHLOG_TESTGEN_DOMAINS=f"{domain}-{domain}", ARCHLOG_TESTGEN_COVERAGE="0")
    done = subprocess.run([sys.executable, "-c", PROMPT_DRIVER, str(node), how], env=env, capture_output=True,
                          text=True, timeout=90, cwd=tmp_path)
    assert done.returncode == 0, done.stderr[-3000:]
    return json.loads(done.stdout.strip().splitlines()[-1])


def test_a_node_waiting_for_the_keyboard_stays_up_on_a_terminal_of_its_own(tmp_path: Path) -> None:
    """A node blocked in input() (a prompt; nothing is typed) is up for the whole example; each process
    reads a pseudo-terminal of its own that the session holds open while it runs and closes when it
    stopped (none is shared by the processes of successive examples)."""
    seen = _prompt(tmp_path, "stop")
    assert len(seen["down"]) >= 20 and set(seen["down"]) == {None}, seen["down"]
    assert all(path.startswith("/dev/pts/") and held == 1 for path, held in seen["terminals"]), seen["terminals"]
    assert seen["held"] == 0 and not seen["listed"]


def test_a_node_killed_outright_is_reported_and_gone_from_the_graph_before_the_next_start(tmp_path: Path) -> None:
    """A node that died by a signal is reported with it; after a stop the dead node's name is no longer
    discovered (it would be until its DDS lease ends, about 20 s, and the next example's namesake would
    look up at once, then die when the lease ends)."""
    seen = _prompt(tmp_path, "kill")
    assert seen["killed"] == "its process was ended by SIGKILL"
    assert seen["held"] == 0 and not seen["listed"]
