"""C++ headers for the workspace's own .msg/.srv/.action files, generated once per content."""

from __future__ import annotations

import hashlib
import json
import os
import subprocess
from pathlib import Path

from archlog.diagnostics import DiagnosticSink
from archlog.extract.cache import cache_dir
from archlog.extract.workspace import Workspace, share_dirs

DEBIAN_PYTHON = Path("/usr/bin/python3")
TEMPLATES = Path("/usr/share/gencpp")
DRIVER = Path(__file__).with_name("gencpp_driver.py")


def generated_headers(workspace: Workspace, diagnostics: DiagnosticSink) -> Path | None:
    """An include folder with headers for every workspace message of ROS 1 packages, or None when
    there are none (or gencpp is not installed: then ports using them are read without their
    types). ROS 2 packages' interfaces get stand-ins from their definitions instead (ros2_stubs.py)."""
    files = [(p.name, f) for p in workspace.packages.values() if not p.ament for kind in ("msg", "srv", "action")
             for f in sorted((p.path / kind).glob(f"*.{kind}"))]
    if not files:
        return None
    digest = hashlib.sha256()
    for pkg, path in files:
        digest.update(f"{pkg}\0{path.name}\0".encode() + path.read_bytes())
    out = cache_dir() / "msg_headers" / digest.hexdigest()[:24]
    if (out / ".done").is_file():
        return out
    if not (DEBIAN_PYTHON.is_file() and TEMPLATES.is_dir()):
        diagnostics.add(workspace.display(files[0][1]), 1, "msg-headers",
                        "gencpp is not installed: C++ ports using this workspace's messages get unknown types", "note")
        return None
    search = [f"{p.name}:{p.path / 'msg'}" for p in workspace.packages.values() if (p.path / "msg").is_dir()]
    search += [f"{d.name}:{d / 'msg'}" for share in share_dirs() if share.is_dir()
               for d in share.iterdir() if (d / "msg").is_dir()]
    request = {"out": str(out), "templates": str(TEMPLATES), "search": search,
               "files": [[pkg, str(path)] for pkg, path in files]}
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    result = subprocess.run([str(DEBIAN_PYTHON), str(DRIVER)], input=json.dumps(request), capture_output=True,
                            text=True, env=env, timeout=300, check=False)
    try:
        errors = json.loads(result.stdout.strip().splitlines()[-1])["errors"]
    except (IndexError, ValueError, KeyError):
        diagnostics.add(workspace.display(files[0][1]), 1, "msg-headers",
                        f"message header generation failed: {result.stderr.strip()[-300:]}", "warning")
        return None
    for path, message in errors:
        diagnostics.add(workspace.display(path), 1, "msg-definition", f"message definition: {message}", "warning")
    (out / ".done").parent.mkdir(parents=True, exist_ok=True)
    (out / ".done").write_text("")
    return out
