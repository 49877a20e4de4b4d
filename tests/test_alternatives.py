"""Names with alternatives (ternaries, if/else) and loops over literal lists, through
composition and the rules."""

from __future__ import annotations

from pathlib import Path

from archlog.analysis import analyse
from archlog.rules.engine import Engine
from archlog.rules.ruleset import load_rules

MANIFEST = ("<package format='2'><name>alt</name><version>0.1.0</version><description>d</description>"
            "<maintainer email='dev@example.com'>m</maintainer><license>MIT</license></package>")
SENSOR = """#!/usr/bin/env python3
import sys
import rospy
from sensor_msgs.msg import LaserScan
rospy.init_node("sensor")
rospy.Publisher("front/scan" if len(sys.argv) > 1 else "rear/scan", LaserScan, queue_size=1)
for side in ("left", "right"):
    rospy.Publisher(side + "/range", LaserScan, queue_size=1)
"""
CONSUMER = """#!/usr/bin/env python3
import rospy
from sensor_msgs.msg import LaserScan
rospy.init_node("consumer")
rospy.Subscriber("front/scan", LaserScan, print)
rospy.Subscriber("left/range", LaserScan, print)
rospy.Subscriber("right/range", LaserScan, print)
"""
WATCHER = """#!/usr/bin/env python3
import rospy
from sensor_msgs.msg import LaserScan
rospy.init_node("watcher")
rospy.Subscriber("back/range", LaserScan, print)
"""


def test_alternatives_and_loops(tmp_path: Path) -> None:
    pkg = tmp_path / "src" / "alt"
    (pkg / "scripts").mkdir(parents=True)
    (pkg / "package.xml").write_text(MANIFEST)
    for name, text in (("sensor.py", SENSOR), ("consumer.py", CONSUMER), ("watcher.py", WATCHER)):
        (pkg / "scripts" / name).write_text(text)
        (pkg / "scripts" / name).chmod(0o755)
    result = analyse([tmp_path], [], {}, [])
    pubs = sorted((port, topic) for port, node, topic, _t in result.store.rows("publisher"))
    assert [t for _p, t in pubs] == ["/front/scan", "/rear/scan", "/left/range", "/right/range"]
    assert pubs[0][0] == pubs[1][0]  # one port, two possible names
    assert pubs[2][0] != pubs[3][0]  # a loop: two ports
    assert [c for _p, c in result.store.rows("alternative_names")] == [2]
    _ctl, findings = Engine(load_rules([])).run(result.store)
    # the scan publisher connects through one of its names, so only /back/range dangles (its
    # type is published elsewhere, under names that are no near miss and that another node hears:
    # AL104, reported once)
    assert sorted((f.rule.id, f.values["topic"]) for f in findings) == [("AL104", "/back/range")]
