"""DDS's own verdict on QoS pairs, next to archlog's (rules AL501-AL505).

One generated ament_python package holds a talker and a listener node; pair number i is the topic
/qos_i, published by the talker and subscribed by the listener with the pair's QoS written in the
source as a user writes it (QoSProfile keywords, Duration(seconds=...)). archlog reads that package
like any workspace; the same two files then run on a private DDS domain, where the listener records,
per topic, whether DDS matched the pair or raised the incompatible-QoS event.
"""

from __future__ import annotations

import itertools
import json
import subprocess
import sys
import tempfile
from pathlib import Path

from archlog.analysis import analyse
from archlog.rules.engine import Engine
from archlog.rules.ruleset import load_rules
from support.ros2_nodes import ros2_env, stop

QOS_RULES = ("AL501", "AL502", "AL503", "AL504", "AL505")
Side = dict[str, object]  # policy -> value (durations in seconds; None: not set, ROS 2's default)


def _sweep(policy: str, pub_values: list, sub_values: list) -> list[tuple[Side, Side]]:
    return [({policy: p}, {policy: s}) for p, s in itertools.product(pub_values, sub_values)]


# Each policy AL501-AL505 reads, swept over its values on both sides (None: the policy left unset),
# and pairs where several policies differ at once.
PAIRS: list[tuple[Side, Side]] = (
    _sweep("reliability", ["reliable", "best_effort", "system_default"], ["reliable", "best_effort", "system_default"])
    + _sweep("durability", ["volatile", "transient_local", "system_default"],
             ["volatile", "transient_local", "system_default"])
    + _sweep("deadline", [None, 0.2, 0.5, 1.0], [None, 0.5])
    + _sweep("liveliness", ["automatic", "manual_by_topic", "system_default"],
             ["automatic", "manual_by_topic", "system_default"])
    + _sweep("liveliness_lease_duration", [None, 0.5, 1.0, 2.0], [None, 1.0])
    + [({"reliability": "best_effort", "durability": "volatile"}, {"reliability": "reliable", "durability": "transient_local"}),
       ({"reliability": "best_effort", "durability": "transient_local"},
        {"reliability": "best_effort", "durability": "transient_local"}),
       ({"deadline": 1.0, "liveliness_lease_duration": 2.0}, {"deadline": 0.5, "liveliness_lease_duration": 1.0}),
       ({"deadline": 0.5, "liveliness": "manual_by_topic"}, {"deadline": 1.0, "liveliness": "manual_by_topic"})]
)

_ENUMS = {"reliability": "ReliabilityPolicy", "durability": "DurabilityPolicy", "liveliness": "LivelinessPolicy"}

PACKAGE_XML = """<?xml version="1.0"?>
<package format="3">
  <name>qos_matrix</name>
  <version>0.0.1</version>
  <description>Publisher/subscriber pairs over QoS combinations</description>
  <maintainer email="dev@example.com">dev</maintainer>
  <license>Apache-2.0</license>
  <exec_depend>rclpy</exec_depend>
  <exec_depend>std_msgs</exec_depend>
  <export><build_type>ament_python</build_type></export>
</package>
"""

SETUP_PY = """from setuptools import setup

setup(name="qos_matrix", version="0.0.1", packages=["qos_matrix"],
      entry_points={"console_scripts": ["talker = qos_matrix.talker:main", "listener = qos_matrix.listener:main"]})
"""

HEADER = """import json
import sys

import rclpy
from rclpy.duration import Duration
from rclpy.event_handler import PublisherEventCallbacks, SubscriptionEventCallbacks
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, LivelinessPolicy, QoSProfile, ReliabilityPolicy
from std_msgs.msg import String
"""

TALKER = """

class Talker(Node):
    def __init__(self):
        super().__init__("talker")
        quiet = PublisherEventCallbacks(incompatible_qos=lambda event: None)
        self.pubs = [
{ports}
        ]


def main():
    rclpy.init()
    rclpy.spin(Talker())
"""

LISTENER = """

class Listener(Node):
    def __init__(self):
        super().__init__("listener")
        self.verdicts = {{}}
        self.subs = [
{ports}
        ]

    def events(self, topic):
        def incompatible(event):
            self.verdicts.setdefault(topic, "incompatible")

        def matched(event):
            if event.current_count > 0:
                self.verdicts.setdefault(topic, "matched")
        return SubscriptionEventCallbacks(incompatible_qos=incompatible, matched=matched)


def main():
    rclpy.init()
    node = Listener()
    while len(node.verdicts) < {count} and rclpy.ok():
        rclpy.spin_once(node, timeout_sec=0.5)
    print(json.dumps(node.verdicts), flush=True)
    sys.stdout.flush()
    rclpy.spin(node)
"""


def _profile(side: Side) -> str:
    words = ["depth=10"]
    for policy, value in side.items():
        if value is None:
            continue
        if policy in _ENUMS:
            words.append(f"{policy}={_ENUMS[policy]}.{str(value).upper()}")
        else:
            words.append(f"{policy}=Duration(seconds={value})")
    return "QoSProfile(" + ", ".join(words) + ")"


def write_workspace(folder: Path) -> Path:
    """The qos_matrix package under folder/src; returns folder."""
    package = folder / "src" / "qos_matrix"
    (package / "qos_matrix").mkdir(parents=True)
    (package / "resource").mkdir()
    (package / "resource" / "qos_matrix").write_text("")
    (package / "package.xml").write_text(PACKAGE_XML)
    (package / "setup.py").write_text(SETUP_PY)
    (package / "qos_matrix" / "__init__.py").write_text("")
    pubs = "\n".join(f'            self.create_publisher(String, "qos_{i}", {_profile(pub)}, event_callbacks=quiet),'
                     for i, (pub, _sub) in enumerate(PAIRS))
    subs = "\n".join(f'            self.create_subscription(String, "qos_{i}", lambda msg: None, {_profile(sub)},\n'
                     f'                                     event_callbacks=self.events("/qos_{i}")),'
                     for i, (_pub, sub) in enumerate(PAIRS))
    (package / "qos_matrix" / "talker.py").write_text(HEADER + TALKER.format(ports=pubs))
    (package / "qos_matrix" / "listener.py").write_text(HEADER + LISTENER.format(ports=subs, count=len(PAIRS)))
    return folder


def archlog_verdicts(workspace: Path) -> tuple[dict[str, list[str]], list[str]]:
    """Per topic, the QoS rules archlog reports (every executable of the workspace runs once), and
    the diagnostics that would make that verdict partial."""
    analysis = analyse([workspace], [], {}, [])
    _ctl, findings = Engine(load_rules([])).run(analysis.store)
    verdicts: dict[str, list[str]] = {f"/qos_{i}": [] for i in range(len(PAIRS))}
    for finding in findings:
        if finding.rule.id in QOS_RULES:
            verdicts[str(finding.values["topic"])].append(finding.rule.id)
    problems = [f"{d.file}:{d.line}: {d.code} {d.message}" for d in analysis.diagnostics.items
                if d.code.startswith(("python", "qos")) or d.severity in ("warning", "error")]
    return verdicts, problems


def dds_verdicts(workspace: Path, domain: int, timeout: float = 60.0) -> dict[str, str]:
    """Per topic, "matched" or "incompatible" as DDS (Fast DDS through rclpy) decides."""
    package = workspace / "src" / "qos_matrix"
    with tempfile.TemporaryDirectory(prefix="archlog-qos-") as tmp:
        env = ros2_env(domain, Path(tmp), (package,))
        start = [sys.executable, "-c"]
        talker = subprocess.Popen([*start, "from qos_matrix.talker import main; main()"], env=env,
                                  stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
        try:
            listener = subprocess.Popen([*start, "from qos_matrix.listener import main; main()"], env=env,
                                        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                                        start_new_session=True)
            try:
                line = _first_line(listener, timeout)
            finally:
                stop(listener)
        finally:
            stop(talker)
    return json.loads(line)


def _first_line(proc: subprocess.Popen, timeout: float) -> str:
    import selectors

    with selectors.DefaultSelector() as selector:
        selector.register(proc.stdout, selectors.EVENT_READ)
        if not selector.select(timeout):
            raise TimeoutError(f"the listener decided no verdict within {timeout} s")
    return proc.stdout.readline()  # type: ignore[union-attr]


def describe(side: Side) -> str:
    return ", ".join(f"{k}={'unset' if v is None else v}" for k, v in side.items())


def matrix(archlog: dict[str, list[str]], dds: dict[str, str]) -> list[dict[str, object]]:
    """One row per pair: both verdicts and whether they agree."""
    rows = []
    for i, (pub, sub) in enumerate(PAIRS):
        topic = f"/qos_{i}"
        said = dds.get(topic, "undecided")
        rows.append({"topic": topic, "publisher": describe(pub), "subscriber": describe(sub), "dds": said,
                     "archlog": archlog[topic], "agree": (said == "incompatible") == bool(archlog[topic])})
    return rows


def markdown(rows: list[dict[str, object]]) -> str:
    lines = ["| topic | publisher | subscriber | DDS | archlog | agree |", "|---|---|---|---|---|---|"]
    lines += [f"| {r['topic']} | {r['publisher']} | {r['subscriber']} | {r['dds']} | "
              f"{', '.join(r['archlog']) or 'compatible'} | {'yes' if r['agree'] else '**no**'} |"  # type: ignore[arg-type]
              for r in rows]
    return "\n".join(lines) + "\n"

