"""Build a corpus workspace's C++ executables with g++ against Debian's ROS headers, in a copy
of the workspace, so that roslaunch can start them (it finds executables inside packages)."""

from __future__ import annotations

import atexit
import hashlib
import shutil
import subprocess
import tempfile
import threading
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from archlog.diagnostics import DiagnosticSink
from archlog.extract.workspace.index import Workspace

LIBS = ["-lroscpp", "-lrosconsole", "-lroscpp_serialization", "-lrostime", "-lboost_system", "-lpthread"]
OPTIONAL_LIBS = {"image_transport": "-limage_transport", "tf2_ros": "-ltf2_ros -ltf2",
                 "actionlib": "-lactionlib -lboost_thread",
                 "tf/": "-ltf", "diagnostic_updater": "-ldiagnostic_updater", "message_filters": "-lmessage_filters",
                 "nodelet": "-lnodeletlib", "pluginlib": "-lclass_loader"}


def build_workspace(variant: Path, target: Path) -> Path:
    """Copy `variant` to `target` and compile every C++ executable into `<pkg>/bin/`; returns the
    copy's src folder. Raises RuntimeError with the compiler's message on failure."""
    shutil.copytree(variant, target)
    workspace = Workspace([target], DiagnosticSink())
    jobs = [(pkg, exe) for pkg in workspace.packages.values() for exe in pkg.executables.values() if exe.lang == "cpp"]
    with ThreadPoolExecutor(max_workers=2) as pool:
        for failure in pool.map(lambda job: _compile(*job), jobs):
            if failure:
                raise RuntimeError(failure)
    return target / "src"


def _compile(package, executable) -> str | None:
    text = "".join(s.read_text(errors="replace") for s in executable.sources)
    extra = [flag for needle, flags in OPTIONAL_LIBS.items() if needle in text for flag in flags.split()]
    out = package.path / "bin" / executable.name
    out.parent.mkdir(exist_ok=True)
    include_dirs = [package.path / "include", *package.include_dirs]
    includes = [f"-I{d}" for d in include_dirs]
    command = ["g++", "-std=c++17", "-O0", "-w", *includes, *map(str, executable.sources), "-o", str(out),
               *extra, *LIBS]
    cached = _cache_path(package.path, executable.sources, include_dirs, [*extra, *LIBS])
    with _key_lock(cached.name):  # a twin built at the same time waits for this build
        if cached.is_file():  # the same sources, headers and flags were built in this session
            shutil.copy2(cached, out)
            return None
        result = subprocess.run(command, capture_output=True, text=True, timeout=600, check=False)
        if result.returncode != 0:
            return f"g++ failed for {executable.name}:\n{result.stderr[-3000:]}"
        shutil.copy2(out, cached)
    return None


_cache_lock = threading.Lock()
_cache_dir: list[Path] = []
_key_locks: dict[str, threading.Lock] = {}


def _key_lock(key: str) -> threading.Lock:
    with _cache_lock:
        return _key_locks.setdefault(key, threading.Lock())


def _cache_path(root: Path, sources: list[Path], include_dirs: list[Path], flags: list[str]) -> Path:
    """Where a build of these sources is kept for this process (twins share their C++ code): keyed by
    the sources' and package headers' paths relative to the package and their contents, and the flags."""
    digest = hashlib.sha256("\0".join(flags).encode())
    headers = sorted(p for d in include_dirs if d.is_dir() and d.is_relative_to(root) for p in d.rglob("*")
                     if p.is_file())
    for path in [*sources, *headers]:
        digest.update(str(path.relative_to(root) if path.is_relative_to(root) else path).encode() + b"\0")
        digest.update(path.read_bytes() + b"\0")
    with _cache_lock:
        if not _cache_dir:
            _cache_dir.append(Path(tempfile.mkdtemp(prefix="archlog-cpp-build-")))
            atexit.register(shutil.rmtree, _cache_dir[0], True)
    return _cache_dir[0] / digest.hexdigest()
