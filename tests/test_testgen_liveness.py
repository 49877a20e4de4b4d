"""Liveness of `requires` (issue 32): a generated test asserts that an output follows its required
inputs only where the behavior facts decide it; Python's walk tells which publish calls and state
writes depend on nothing but their trigger and guards."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest
from support.testgen_corpus import CORPUS

from archlog.diagnostics import DiagnosticSink
from archlog.extract.python.node import extract_python

NODE = '''
import rospy
from sensor_msgs.msg import Range
from std_msgs.msg import Float32

class Fill:
    def __init__(self):
        self.latest = None
        self.items = []
        self.pub = rospy.Publisher("out", Float32, queue_size=1)
        rospy.Subscriber("in", Range, self.on_range)

    def on_range(self, msg):
        self.latest = msg
        if msg.range > 1.0:
            self.items.append(msg)

    def run(self):
        while not rospy.is_shutdown():
            if self.latest is not None:
                self.pub.publish(Float32(1.0))
            if self.latest is not None and self.latest.max_range > 0:
                self.pub.publish(Float32(2.0))
            for item in self.items:
                self.pub.publish(Float32(3.0))
            try:
                value = 1.0 / self.latest.max_range
            except ZeroDivisionError:
                continue
            self.pub.publish(Float32(value))
            if not self.items:
                self.pub.publish(Float32(5.0))
            rospy.sleep(0.1)

if __name__ == "__main__":
    rospy.init_node("fill")
    Fill().run()
'''


def test_the_walk_tells_which_paths_their_guards_decide(tmp_path: Path) -> None:
    path = tmp_path / "fill.py"
    path.write_text(NODE)
    summary = extract_python(path, "pkg", "fill.py", "fill.py", DiagnosticSink())
    decided = {p.line: p.decided for p in summary.publishes}
    assert decided == {21: True, 23: False, 25: False, 30: False, 32: False}
    writes = {(w.var, w.line): w.decided for w in summary.writes}
    assert writes[("Fill.latest", 14)] and writes[("Fill.latest", 8)]
    assert not writes[("Fill.items", 16)]  # only when the range exceeds 1.0


def _model(variant: Path, tmp_path: Path) -> dict[str, Any]:
    subprocess.run([sys.executable, "-m", "archlog", "testgen", str(variant), "--launch", "sonar_fill/launch/fill.launch",
                    "--output", str(tmp_path)], check=True, capture_output=True, text=True, timeout=120)
    namespace: dict[str, Any] = {}
    source = (tmp_path / "test_fill.py").read_text()
    exec(source[source.index("MODEL = "):source.index("SETTINGS = ")], namespace)  # the model is a literal
    return namespace["MODEL"]


@pytest.mark.parametrize(("variant", "follows"), [("clean", {}), ("buggy", {"/fill_ratio": 0.1})])
def test_a_field_comparison_on_the_way_leaves_liveness_undecided(variant: str, follows: dict, tmp_path: Path) -> None:
    """The fixed twin publishes only while max_range > 0, which no guard models: its test must not
    expect /fill_ratio after every Range, and its header says so; the buggy twin's guard (a Range
    came) is set by the input's callback alone, so there the output must follow."""
    model = _model(CORPUS / "guarded_division" / variant, tmp_path)
    assert model["requires"] == {"/fill_ratio": ["/sonar/front"]}
    assert model["follows"] == follows
    header = (tmp_path / "test_fill.py").read_text().split('"""')[1]
    assert ("Not generated (undecided)" in header) == (variant == "clean")
    assert (list(model["undecided"]) == ["/fill_ratio"]) == (variant == "clean")
