"""C++ headers for the workspace's own .msg/.srv/.action files, generated once per content."""

from __future__ import annotations

import hashlib
import json
import os
import subprocess
import tempfile
from pathlib import Path

from archlog import sandbox
from archlog.diagnostics import DiagnosticSink
from archlog.extract.cpp.cache import cache_dir
from archlog.extract.workspace.index import Workspace
from archlog.extract.workspace.packages import share_dirs

DEBIAN_PYTHON = Path("/usr/bin/python3")
TEMPLATES = Path("/usr/share/gencpp")
DRIVER = Path(__file__).with_name("gencpp_driver.py")


def generated_headers(workspace: Workspace, diagnostics: DiagnosticSink) -> Path | None:
    """An include folder with headers for every workspace message of ROS 1 packages, or None when
    there are none (or gencpp is not installed: then ports using them are read without their
    types). ROS 2 packages' interfaces get stand-ins from their definitions instead (stubs.py).
    The generator reads copies of the definitions the sandbox allows, never the workspace itself."""
    texts = _definitions(workspace, diagnostics)
    if not texts:
        return None
    digest = hashlib.sha256()
    for (pkg, kind, name), (path, text) in texts.items():  # the path: the diagnostics kept name it
        digest.update(f"{pkg}\0{name}.{kind}\0{workspace.display(path)}\0".encode() + text)
    out = cache_dir() / "msg_headers" / digest.hexdigest()[:24]
    if (out / ".done").is_file():
        _report(out / ".done", diagnostics)
        return out
    first = workspace.display(next(iter(texts.values()))[0])
    if not (DEBIAN_PYTHON.is_file() and TEMPLATES.is_dir()):
        diagnostics.add(first, 1, "msg-headers",
                        "gencpp is not installed: C++ ports using this workspace's messages get unknown types", "note")
        return None
    with tempfile.TemporaryDirectory(prefix="archlog-msg-") as staging:
        copies = _stage(texts, Path(staging))
        search = sorted({f"{pkg}:{Path(staging) / pkg / 'msg'}" for pkg, kind, _name in texts if kind == "msg"})
        search += [f"{d.name}:{d / 'msg'}" for share in share_dirs() if share.is_dir()
                   for d in share.iterdir() if (d / "msg").is_dir()]
        request = {"out": str(out), "templates": str(TEMPLATES), "search": search,
                   "files": [[pkg, str(copy)] for copy, (pkg, _original) in copies.items()]}
        env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
        result = subprocess.run([str(DEBIAN_PYTHON), str(DRIVER)], input=json.dumps(request), capture_output=True,
                                text=True, env=env, timeout=300, check=False)
    try:
        errors = json.loads(result.stdout.strip().splitlines()[-1])["errors"]
    except (IndexError, ValueError, KeyError):
        diagnostics.add(first, 1, "msg-headers",
                        f"message header generation failed: {result.stderr.strip()[-300:]}", "warning")
        return None
    shown = [(workspace.display(copies[Path(path)][1] if Path(path) in copies else Path(path)), message)
             for path, message in errors]
    (out / ".done").parent.mkdir(parents=True, exist_ok=True)
    (out / ".done").write_text(json.dumps(shown))
    _report(out / ".done", diagnostics)
    return out


def _report(done: Path, diagnostics: DiagnosticSink) -> None:
    """The definitions that did not generate (kept in `done`, so a cached run reports them too)."""
    try:
        shown = json.loads(done.read_text() or "[]")
    except (OSError, ValueError):
        shown = []
    for entry in shown if isinstance(shown, list) else []:
        if isinstance(entry, list) and len(entry) == 2:
            diagnostics.add(str(entry[0]), 1, "msg-definition", f"message definition: {entry[1]}", "warning")


Definitions = dict[tuple[str, str, str], tuple[Path, bytes]]


def _definitions(workspace: Workspace, diagnostics: DiagnosticSink) -> Definitions:
    """Every .msg/.srv/.action file of the workspace's ROS 1 packages, (path, bytes) by (package,
    kind, name); a file the sandbox refuses is a diagnostic."""
    texts: Definitions = {}
    for package in workspace.packages.values():
        if package.ament:
            continue
        for kind in ("msg", "srv", "action"):
            for path in sorted((package.path / kind).glob(f"*.{kind}")):
                try:
                    texts[(package.name, kind, path.stem)] = (path, sandbox.read_bytes(path, "message"))
                except sandbox.Refused as exc:
                    diagnostics.add(workspace.display(path), 1, exc.code, f"not read: {exc}", "warning")
    return texts


def _stage(texts: Definitions, folder: Path) -> dict[Path, tuple[str, Path]]:
    """Copies of the definitions under folder/PKG/KIND/, each mapped to (package, original)."""
    copies = {}
    for (pkg, kind, name), (original, text) in texts.items():
        copy = folder / pkg / kind / f"{name}.{kind}"
        copy.parent.mkdir(parents=True, exist_ok=True)
        copy.write_bytes(text)
        copies[copy] = (pkg, original)
    return copies
