"""Build a corpus workspace's C++ executables with g++ against Debian's ROS headers, in a copy
of the workspace, so that roslaunch can start them (it finds executables inside packages)."""

from __future__ import annotations

import shutil
import subprocess
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from archlog.diagnostics import DiagnosticSink
from archlog.extract.workspace import Workspace

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
    includes = [f"-I{package.path / 'include'}", *(f"-I{d}" for d in package.include_dirs)]
    command = ["g++", "-std=c++17", "-O0", "-w", *includes, *map(str, executable.sources), "-o", str(out),
               *extra, *LIBS]
    result = subprocess.run(command, capture_output=True, text=True, timeout=600, check=False)
    return None if result.returncode == 0 else f"g++ failed for {executable.name}:\n{result.stderr[-3000:]}"
