"""The QoS matrix of tests/test_qos_dds.py written to bench/results/qos_dds.md: every pair, DDS's
verdict (Fast DDS through rclpy, from PyPI) and archlog's (rules AL501-AL505).

    nice -n 10 python bench/qos_dds.py [--domain N]
"""

from __future__ import annotations

import argparse
import importlib.metadata
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tests"))

from support.qos_dds import archlog_verdicts, dds_verdicts, markdown, matrix, write_workspace  # noqa: E402

OUT = ROOT / "bench" / "results" / "qos_dds.md"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--domain", type=int, default=120, help="a ROS_DOMAIN_ID nothing else uses")
    options = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        workspace = write_workspace(Path(tmp))
        said, problems = archlog_verdicts(workspace)
        dds = dds_verdicts(workspace, options.domain)
    rows = matrix(said, dds)
    agree = sum(1 for r in rows if r["agree"])
    incompatible = sum(1 for r in rows if r["dds"] == "incompatible")
    versions = ", ".join(f"{d} {importlib.metadata.version(d)}" for d in ("ros-rclpy", "ros-rmw-fastrtps-cpp", "ros-fastdds"))
    OUT.write_text(
        "# QoS rules against DDS\n\n"
        f"`nice -n 10 python bench/qos_dds.py` ({versions}; the test is tests/test_qos_dds.py).\n\n"
        "Each row is one publisher/subscriber pair on its own topic, written as rclpy code (QoSProfile keywords;\n"
        "`unset` leaves the policy at ROS 2's default). archlog read the generated package like any workspace;\n"
        "the same code then ran on a private DDS domain, where the listener recorded whether DDS matched the\n"
        "pair or raised the incompatible-QoS event. archlog's verdict is the QoS findings it reports on the topic.\n\n"
        f"**{agree} of {len(rows)} pairs agree** ({incompatible} incompatible for DDS, "
        f"{len(rows) - incompatible} matched); diagnostics while reading: {len(problems)}.\n\n"
        "`system_default` is what the middleware chooses: with Fast DDS a writer is reliable and transient local\n"
        "and a reader best effort and volatile, so a system-default side never made a pair incompatible here;\n"
        "the rules report only explicit values (another middleware's defaults could differ).\n\n"
        + markdown(rows), encoding="utf-8")
    print(f"{agree}/{len(rows)} agree; wrote {OUT}")


if __name__ == "__main__":
    main()
