"""Every import that archlog, its tests and its benchmarks make is declared in pyproject.toml:
runtime imports in `dependencies`, test imports in the `test` extra (issue 14). A missing
declaration fails here, not on a new user's machine."""

from __future__ import annotations

import ast
import fnmatch
import importlib.metadata
import re
import subprocess
import sys
import textwrap
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

# Scripts that run under Debian's /usr/bin/python3 (ROS 1 imports only there), started as
# subprocesses: their imports come from Debian's packages (debian-packages.txt), not from PyPI.
DEBIAN_PYTHON = {
    "archlog/extract/cpp/gencpp_driver.py",
    "archlog/testgen/debian/bridge.py",
    "archlog/testgen/debian/launch.py",
    "bench/debian_nodes/feeder.py",
    "tests/support/roslaunch_oracle.py",
    "tests/support/topic_monitor.py",
}
LOCAL = {"archlog", "support", "rosidl_standin",  # tests/support/ros2_standin: a stand-in for ROS 2's Python API
         *(p.stem for folder in ("tests", "bench") for p in (ROOT / folder).glob("*.py"))}  # modules beside each other


def _normal(dist: str) -> str:
    return re.sub(r"[-_.]+", "-", dist).lower()


def _names(requirements: list[str]) -> set[str]:
    return {_normal(re.match(r"[A-Za-z0-9._-]+", r.strip()).group()) for r in requirements}


# archlog modules that may import an extra, lazily (archlog imports without it): the `ros2` extra
# (rclpy), the `coverage` extra (line coverage of the nodes under a generated test)
OPTIONAL = {"archlog/observe_ros2.py": "ros2", "archlog/testgen/ros2.py": "coverage", "archlog/testgen/lines.py": "coverage"}


def declared() -> tuple[set[str], set[str]]:
    """(runtime, test) distribution names as pyproject.toml declares them; the tests may use the
    `ros2` extra too (.ci/run installs both)."""
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    extras = project["optional-dependencies"]
    return _names(project["dependencies"]), _names(extras["test"]) | extra()


def extra(name: str = "ros2") -> set[str]:
    return _names(tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["optional-dependencies"][name])


def providers() -> dict[str, set[str]]:
    """Top-level module -> the installed distributions that provide it."""
    return {module: {_normal(d) for d in dists}
            for module, dists in importlib.metadata.packages_distributions().items()}


def imports(path: Path) -> set[str]:
    """Top-level names of every absolute import in a file, at any depth (lazy imports too)."""
    found: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text(), str(path))):
        if isinstance(node, ast.Import):
            found |= {alias.name.split(".")[0] for alias in node.names}
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            found.add(node.module.split(".")[0])
    return found


def undeclared(files: list[Path], allowed: set[str], provided: dict[str, set[str]]) -> list[str]:
    """`file: module` for every import that is neither stdlib, local nor from an allowed distribution."""
    problems = []
    for path in files:
        for module in sorted(imports(path) - set(sys.stdlib_module_names) - LOCAL):
            if not provided.get(module, set()) & allowed:
                problems.append(f"{path.relative_to(ROOT) if path.is_relative_to(ROOT) else path}: {module}")
    return problems


def _files(*folders: str) -> list[Path]:
    return [p for folder in folders for p in sorted((ROOT / folder).rglob("*.py"))
            if p.relative_to(ROOT).as_posix() not in DEBIAN_PYTHON]


def test_debian_python_scripts_exist() -> None:
    assert all((ROOT / f).is_file() for f in DEBIAN_PYTHON)


def test_runtime_imports_are_dependencies() -> None:
    runtime, _test = declared()
    files = _files("archlog")
    assert undeclared([f for f in files if f.relative_to(ROOT).as_posix() not in OPTIONAL], runtime,
                      providers()) == []
    for file, name in sorted(OPTIONAL.items()):
        assert undeclared([ROOT / file], runtime | extra(name), providers()) == []


def test_test_and_bench_imports_are_declared() -> None:
    runtime, test = declared()
    assert undeclared(_files("tests", "bench"), runtime | test, providers()) == []


def test_an_undeclared_import_is_caught(tmp_path: Path) -> None:
    source = tmp_path / "module.py"
    source.write_text("import yaml\n\ndef f():\n    import parso\n    from rich.console import Console\n")
    provided = providers()
    assert undeclared([source], {"pyyaml", "rich"}, provided) == [f"{source}: parso"]
    assert undeclared([source], {"pyyaml", "rich", "parso"}, provided) == []


def test_installed_package_imports_with_only_its_declared_requirements(tmp_path: Path) -> None:
    """Import every module of the installed distribution in a fresh interpreter (isolated mode, run
    outside the source tree) where an import made by archlog of anything but the standard library,
    archlog itself or a declared runtime requirement fails, as it would on a fresh machine."""
    runtime, _test = declared()
    allowed = sorted(m for m, dists in providers().items() if dists & runtime)
    script = textwrap.dedent(f"""
        import builtins, importlib, pkgutil, sys
        allowed = set({allowed!r}) | set(sys.stdlib_module_names) | {{"archlog"}}
        real_import = builtins.__import__

        def guarded(name, globals=None, locals=None, fromlist=(), level=0):
            importer = (globals or {{}}).get("__name__", "")
            if level == 0 and importer.split(".")[0] == "archlog" and name.split(".")[0] not in allowed:
                raise ModuleNotFoundError(f"{{importer}} imports {{name}}, which is not declared")
            return real_import(name, globals, locals, fromlist, level)

        builtins.__import__ = guarded
        import archlog
        names = [m.name for m in pkgutil.walk_packages(archlog.__path__, "archlog.")]
        for name in names:
            if name != "archlog.__main__":  # runs the command line
                importlib.import_module(name)
        print(len(names))
    """)
    done = subprocess.run([sys.executable, "-I", "-c", script], cwd=tmp_path, capture_output=True,
                          text=True, timeout=120)
    assert done.returncode == 0, done.stderr[-3000:]
    assert int(done.stdout.split()[-1]) > 50


def test_every_data_file_of_archlog_is_installed() -> None:
    """Files archlog reads at run time beside its modules (rules, models, stand-in headers, rule
    fixtures that `archlog rule ID` quotes) match a package-data glob, so `pip install .` ships
    them, not only an editable checkout."""
    globs = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]["package-data"]["archlog"]
    tracked = subprocess.run(["git", "ls-files", "archlog"], cwd=ROOT, capture_output=True, text=True,
                             check=True).stdout.split()
    data = [Path(f).relative_to("archlog").as_posix() for f in tracked if not f.endswith(".py")]
    missing = [f for f in data if not any(fnmatch.fnmatch(f, g) and f.count("/") == g.count("/") for g in globs)]
    assert data and not missing, missing
