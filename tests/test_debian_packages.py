"""Every Debian package the suite needs is declared in debian-packages.txt (issue 36): the headers the
ROS 1 corpus's C++ includes, the nodes its runtime systems launch (executable and the package.xml
roslaunch looks for) and the modules their Python nodes import. A machine where someone installed a
package by hand passes the suite only if that package is declared (or comes with a declared one),
so a fresh machine running `.ci/run` has it too. Each failure names the file, what it needs and the
Debian package that provides it (or that none is installed)."""

from __future__ import annotations

import ast
import json
import re
import subprocess
from functools import cache
from pathlib import Path

import pytest
from conftest import ROOT, requires_ros
from support.live_graph import SYSTEM_PYTHON

from archlog.diagnostics import DiagnosticSink
from archlog.extract.cpp.extract import _nested_include_roots
from archlog.extract.workspace.index import Workspace

pytestmark = requires_ros()

CORPUS = ROOT / "corpus"
# C++ fixtures with golden extractions or compiled by runtime tests, ROS 1 code only (the rclcpp
# corpus uses archlog's stand-in headers). corpus/workspace's fixtures keep the headers a real package
# generates at build time (dynamic_reconfigure's), which no Debian package provides.
CPP_FOLDERS = ["cpp_ros1", "cpp_ros1_files", "ros1", "behavior", "testgen"]


def runtime_systems() -> list[Path]:
    """The systems tests launch with Debian's roslaunch: corpus/ros1 cases marked `runtime`, and every
    behavior and testgen system."""
    marked = [case.parent for case in sorted((CORPUS / "ros1").glob("*/*/case.json"))
              if json.loads(case.read_text()).get("runtime")]
    return marked + sorted(p.parent for folder in ("behavior", "testgen") for p in (CORPUS / folder).glob("*/*/case.json"))


def declared() -> set[str]:
    lines = (ROOT / "debian-packages.txt").read_text().splitlines()
    return {line.strip() for line in lines if line.strip() and not line.startswith("#")}


@cache
def _installed_depends() -> dict[str, set[str]]:
    """Installed package -> the packages its Depends and Pre-Depends name (every alternative)."""
    out = subprocess.run(["dpkg-query", "-W", "-f", "${Package}\t${Depends}, ${Pre-Depends}\n"],
                         capture_output=True, text=True, check=True).stdout
    depends: dict[str, set[str]] = {}
    for line in out.splitlines():
        package, _tab, rest = line.partition("\t")
        depends[package] = {re.split(r"[\s:(]", alt.strip())[0] for alt in re.split(r"[,|]", rest) if alt.strip()}
    return depends


@cache
def installed_by_declaration() -> frozenset[str]:
    """The declared packages and everything they bring with them (recursive Depends)."""
    depends = _installed_depends()
    seen: set[str] = set()
    todo = list(declared())
    while todo:
        package = todo.pop()
        if package not in seen:
            seen.add(package)
            todo.extend(depends.get(package, ()))
    return frozenset(seen)


def owners(paths: set[Path]) -> dict[Path, str]:
    """The Debian package that installed each path (paths no package owns are left out)."""
    if not paths:
        return {}
    done = subprocess.run(["dpkg-query", "-S", *map(str, sorted(paths))], capture_output=True, text=True)
    found: dict[Path, str] = {}
    for line in done.stdout.splitlines():
        package, _sep, path = line.partition(": ")
        found[Path(path.strip())] = package.split(",")[0].split(":")[0].strip()
    return found


def undeclared(needs: dict[Path, str]) -> list[str]:
    """`what needs it: path (package)` for every needed system path whose package is not declared."""
    by_path = owners(set(needs))
    problems = []
    for path, who in sorted(needs.items()):
        package = by_path.get(path) or by_path.get(path.resolve())
        if package is None:
            problems.append(f"{who}: {path} belongs to no installed Debian package")
        elif package not in installed_by_declaration():
            problems.append(f"{who}: {path} comes from Debian package {package}, which debian-packages.txt does not "
                            f"declare (nor any package it depends on)")
    return problems


def _expects_missing_headers(source: Path) -> bool:
    """A fixture whose golden extraction records a compile problem, or a stand-in archlog used for a
    missing ROS 1 header, includes on purpose a header that no installed package provides (a vendor
    library, a generated config header, a ROS 1 header Debian does not package)."""
    expected = source.with_name(source.name + ".expected")
    folder_expected = next((p.with_name(p.name + ".expected") for p in source.parents if p.parent.name == "cpp_ros1_files"),
                           None)
    return any(p is not None and p.is_file() and ("cpp-compile" in (text := p.read_text()) or "cpp-ros1-stand-in" in text)
               for p in (expected, folder_expected))


def _include_dirs(source: Path) -> list[Path]:
    dirs = [source.parent]
    for parent in source.parents:
        if (parent / "include").is_dir():
            dirs.append(parent / "include")
        if parent == CORPUS:
            break
    return dirs


def header_needs() -> tuple[dict[Path, str], list[str]]:
    """System headers the ROS 1 corpus's C++ files include (as g++ resolves them), and the headers
    that no installed package provides."""
    needs: dict[Path, str] = {}
    missing: list[str] = []
    sources = sorted(p for folder in CPP_FOLDERS for p in (CORPUS / folder).rglob("*.cpp")
                     if "rclcpp" not in p.read_text(errors="replace"))
    for source in sources:
        flags = [f"-I{d}" for d in [*_include_dirs(source), *_nested_include_roots()]]
        done = subprocess.run(["g++", "-std=c++17", "-M", "-MG", *flags, str(source)], capture_output=True, text=True,
                              timeout=120)
        assert done.returncode == 0, done.stderr
        names = done.stdout.replace("\\\n", " ").split(":", 1)[1].split()
        where = str(source.relative_to(ROOT))
        for name in names:
            path = Path(name)
            if path.is_absolute() and path.parts[1] == "usr":
                needs.setdefault(path, where)
            elif not path.is_absolute() and not path.exists() and not _expects_missing_headers(source):
                missing.append(f"{where}: #include <{name}> is found nowhere (install and declare its Debian package)")
    return needs, missing


def _launch_files() -> list[Path]:
    return sorted(p for system in runtime_systems() for p in system.rglob("*.launch"))


def node_needs() -> tuple[dict[Path, str], list[str]]:
    """For each `<node pkg= type=>` of a runtime system whose package is not in the corpus: the
    package.xml roslaunch finds it by and the executable it starts."""
    local = {pkg for launch in _launch_files()
             for pkg in Workspace([launch.parents[2] if launch.parent.name == "launch" else launch.parent],
                                  DiagnosticSink()).packages}
    needs: dict[Path, str] = {}
    missing: list[str] = []
    for launch in _launch_files():
        for pkg, type_ in re.findall(r'<node\b[^>]*?\bpkg="([^"$]+)"[^>]*?\btype="([^"$]+)"', launch.read_text()):
            if pkg in local:
                continue
            where = f"{launch.relative_to(ROOT)} ({pkg}/{type_})"
            manifest, executable = Path("/usr/share") / pkg / "package.xml", Path("/usr/lib") / pkg / type_
            for path in (manifest, executable):
                if path.exists():
                    needs.setdefault(path, where)
                else:
                    missing.append(f"{where}: roslaunch needs {path}, which no installed package provides")
    return needs, missing


def _local_modules(script: Path) -> set[str]:
    package = next((p for p in script.parents if (p / "package.xml").is_file()), script.parent)
    return {p.stem for p in package.rglob("*.py")} | {p.name for p in package.rglob("*") if p.is_dir()}


def import_needs() -> tuple[dict[Path, str], list[str]]:
    """The modules the runtime systems' Python nodes import, as Debian's python3 finds them."""
    wanted: dict[str, str] = {}
    for system in runtime_systems():
        for script in sorted(system.rglob("*.py")):
            try:
                tree = ast.parse(script.read_text())
            except SyntaxError:  # a Python 2 fixture; the runtime twins are Python 3
                continue
            modules = {alias.name.split(".")[0] for node in ast.walk(tree) if isinstance(node, ast.Import)
                       for alias in node.names}
            modules |= {node.module.split(".")[0] for node in ast.walk(tree)
                        if isinstance(node, ast.ImportFrom) and node.level == 0 and node.module}
            for module in sorted(modules - _local_modules(script)):
                wanted.setdefault(module, str(script.relative_to(ROOT)))
    probe = ("import importlib.util, sys\nfor name in sys.argv[1:]:\n"
             "    spec = importlib.util.find_spec(name)\n"
             "    print(name, spec.origin if spec and spec.origin else ('-' if spec is None else 'builtin'))\n")
    out = subprocess.run([SYSTEM_PYTHON, "-c", probe, *sorted(wanted)], capture_output=True, text=True, check=True,
                         timeout=60).stdout
    needs: dict[Path, str] = {}
    missing: list[str] = []
    for line in out.splitlines():
        name, origin = line.split(" ", 1)
        who = f"{wanted[name]} (import {name})"
        if origin == "-":
            missing.append(f"{who}: Debian's python3 cannot import it (install and declare its Debian package)")
        elif origin.startswith("/usr/lib/python3/dist-packages/"):
            needs[Path(origin)] = who
    return needs, missing


@pytest.mark.parametrize("what", [header_needs, node_needs, import_needs], ids=["headers", "launched-nodes", "imports"])
def test_every_debian_package_the_suite_needs_is_declared(what) -> None:
    needs, missing = what()
    assert needs, "nothing was resolved: the check would pass vacuously"
    assert missing + undeclared(needs) == []


def test_the_check_names_an_undeclared_package() -> None:
    """git is on the machine, but nothing in debian-packages.txt declares or depends on it."""
    problems = undeclared({Path("/usr/bin/git"): "example"})
    assert problems == ["example: /usr/bin/git comes from Debian package git, which debian-packages.txt does not "
                        "declare (nor any package it depends on)"]
