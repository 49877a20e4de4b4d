"""The Python modules of a script's own ROS package that it imports from (`from pkg.module import
Node`): a rospy script often only starts a node class its package's library defines
(camera_calibration's cameracheck.py and `camera_checker.CameraCheckerNode`).

A module is looked for under the package's folder (the nearest one above the script with a
package.xml), in `src/` (catkin_python_setup) or at the top (ament_python); only files the sandbox
lets archlog read are read. Nothing is imported or run.
"""

from __future__ import annotations

import ast
import re
from dataclasses import dataclass
from pathlib import Path

from archlog import sandbox

_FROM = re.compile(r"^\s*from\s+([A-Za-z_][\w.]*)\s+import\b", re.MULTILINE)
_DEPTH = 8  # folders between a script and its package.xml


@dataclass(frozen=True)
class Module:
    """A module of the script's package it imports from (`dotted`, as the script names it), and its source."""

    dotted: str
    path: Path
    data: bytes


def package_modules(script: Path, source: str) -> list[Module]:
    """The modules of the script's package named in its `from X.Y import ...` lines, read."""
    root = _package_root(script)
    if root is None:
        return []
    found: dict[Path, Module] = {}
    for dotted in dict.fromkeys(_FROM.findall(source)):
        for path in _candidates(root, dotted):
            if path not in found and path != script and sandbox.current().inside(path) and path.is_file():
                try:
                    found[path] = Module(dotted, path, sandbox.read_bytes(path, "source"))
                except sandbox.Refused:
                    continue
    return list(found.values())


def imported_calls(tree: ast.Module, modules: list[Module]) -> dict[Module, set[str]]:
    """The names a script imports from each module and calls (a class it instantiates, a function)."""
    dotted = {m.dotted for m in modules}
    imported = {alias.asname or alias.name: (node.module, alias.name) for node in ast.walk(tree)
                if isinstance(node, ast.ImportFrom) and node.module in dotted and not node.level for alias in node.names}
    called = {imported[node.func.id] for node in ast.walk(tree)
              if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id in imported}
    return {m: {name for module, name in called if module == m.dotted} for m in modules}


def _candidates(root: Path, dotted: str) -> list[Path]:
    """Where module `dotted` of the package at `root` may be: src/ first, as a file or a package."""
    parts = dotted.split(".")
    return [path for base in (root / "src", root)
            for path in (base.joinpath(*parts).with_suffix(".py"), base.joinpath(*parts, "__init__.py"))]


def _package_root(script: Path) -> Path | None:
    """The nearest folder above a script holding a package.xml, within the sandbox."""
    for folder in list(script.parents)[:_DEPTH]:
        if not sandbox.current().inside(folder):
            return None
        if (folder / "package.xml").is_file():
            return folder
    return None
