"""A fast slice of oracle 1 (issue 17, bench/debian_nodes.py): a few of Debian's ROS 1 nodes launched on
a loopback master with their inputs, observed, and compared with archlog's recovery from Debian's
source packages (extracted with `apt-get source` into $ARCHLOG_DEBSRC, default /work/debsrc).

The baselines are the measured figures: recovery must not get worse. They are to be raised (missed
lowered, extra lowered) as recovery improves; update them from `python bench/debian_nodes.py --only ...`.
"""

from __future__ import annotations

import dataclasses
import importlib.util
import os
import sys
from pathlib import Path

import pytest
from conftest import ROOT, requires_ros

DEBSRC = Path(os.environ.get("ARCHLOG_DEBSRC", "/work/debsrc"))
_spec = importlib.util.spec_from_file_location("debian_nodes", ROOT / "bench" / "debian_nodes.py")
bench = importlib.util.module_from_spec(_spec)
sys.modules["debian_nodes"] = bench  # dataclasses look their module up there
_spec.loader.exec_module(bench)
CASES = {c.name: c for c in bench.CASES}

# case -> (observed ports, most missed ports, most extra ports), as measured: lower the maxima as
# recovery improves (a drop in observed ports means the node did not come alive as it used to).
BASELINE = {
    "nodelet_rectify": (6, 0, 0),  # ros-image-pipeline nodelet in a manager (ports credited to /manager)
    "image_proc": (17, 0, 0),  # loads debayer and two rectify nodelets into itself (nodelet::Loader)
    "hd_monitor": (1, 0, 0),  # ros-diagnostics, Python
    "robot_state_publisher": (3, 0, 0),  # ports in a catkin library it links (joint_state_listener.cpp)
    "mux": (11, 0, 0),  # ros-comm topic_tools: names from argv (the model's); the output's type is its inputs'
    "relay": (3, 0, 0),  # fed by `rostopic pub` (its model): the output has the type that node publishes
    "rosbag_record_publish": (2, 0, 0),  # recorder.cpp's ports follow the model's conditions (-p; never snapshot)
    "tf2_buffer_server": (7, 0, 0),  # its action server is named by main() in another file (call-site summaries)
    "image_rotate": (9, 0, 0),  # a reconfigure server without a handle: the process's private namespace
    "tf_static_transform_publisher": (1, 0, 0),  # the tf library's listener ports are never reached (reach.py)
    "cameracheck": (6, 0, 0),  # rospy: subscribers in a comprehension, in a class of the package's own module
}

# case -> the same for the nodelet mechanism's own ports (manager services, bonds, loader processes)
INFRA_BASELINE = {"nodelet_rectify": (7, 0, 0)}

pytestmark = [*requires_ros(),
              pytest.mark.skipif(not all((DEBSRC / bench.SOURCES[CASES[c].package]).is_dir() for c in BASELINE),
                                 reason=f"Debian source packages not extracted in {DEBSRC}")]


@pytest.mark.parametrize("name", sorted(BASELINE))
def test_debian_node_recovery_does_not_regress(name: str, tmp_path: Path) -> None:
    observed, most_missed, most_extra = BASELINE[name]
    case = dataclasses.replace(CASES[name], settle=2.0)  # the graph settles in 2 s on these
    result = bench.run_case(case, DEBSRC, tmp_path)
    own = result["own"]
    assert own["observed"] >= observed, f"{name} did not come alive as before: {result.get('logs')}"
    assert len(own["missed"]) <= most_missed, f"{name} misses more ports than before: {own['missed']}"
    assert len(own["extra"]) <= most_extra, f"{name} recovers more ports that do not exist: {own['extra']}"
    if name in INFRA_BASELINE:
        observed, most_missed, most_extra = INFRA_BASELINE[name]
        infra = result["infra"]
        assert infra["observed"] >= observed, f"{name}: fewer nodelet infrastructure ports observed: {infra}"
        assert len(infra["missed"]) <= most_missed, f"{name}: nodelet infrastructure missed: {infra['missed']}"
        assert len(infra["extra"]) <= most_extra, f"{name}: nodelet infrastructure extra: {infra['extra']}"
