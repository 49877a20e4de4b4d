"""`archlog replay FILE`: run a failing example's messages again against the configuration: the
same parameters, messages (after mutation), service calls and pauses, then the same properties."""

from __future__ import annotations

import json
import time
from pathlib import Path

from archlog.testgen.runtime import ArchitectureMachine, close_sessions
from archlog.testgen.settings import Settings


def replay_file(path: Path) -> bool:
    """True when every property holds this time (the failure did not reproduce)."""
    data = json.loads(path.read_text(encoding="utf-8"))

    class Replay(ArchitectureMachine):
        model = data["model"]
        settings = Settings.from_dict(data["settings"])

    machine = Replay()
    print(f"replaying {len(data['actions'])} step(s) of {path}; it failed with: {data['reason']}")
    try:
        for action in data["actions"]:
            if action["op"] == "params":
                machine.start(action["params"])
            elif action["op"] == "publish":
                machine._send(action["topic"], action["msg"])
            elif action["op"] == "call":
                machine.call(action["service"], action["request"])
            elif action["op"] == "spin":
                time.sleep(action["seconds"])
            machine.properties_hold()
        machine.teardown()
    except AssertionError as exc:
        print(f"reproduced: {exc}")
        return False
    finally:
        close_sessions()
    print("every property held")
    return True
