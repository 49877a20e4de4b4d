"""What one C++ file contributes to its executable's summary (cached per file)."""

from __future__ import annotations

from dataclasses import dataclass, field

from archlog.diagnostics import Diagnostic
from archlog.extract.cpp.behavior import FileBehavior
from archlog.extract.cpp.callers import Sites
from archlog.extract.cpp.reach import CallGraph
from archlog.extract.summary import LoadedNodelet, Port
from archlog.values import Value


@dataclass
class FileResult:
    """What one C++ file contributes to its executable's summary."""

    ports: list[Port] = field(default_factory=list)
    default_name: Value | None = None
    anonymous: bool = False
    name_file: str = ""
    name_line: int = 0
    namespace: Value = ""
    infrastructure: tuple[str, ...] = ()  # built-in port groups its node asks for (a lifecycle node)
    without: tuple[str, ...] = ()  # default built-in port groups its node turns off (NodeOptions)
    incomplete: str | None = None
    params_dynamic: str = ""  # why its parameters are not all known (see NodeSummary.params_dynamic)
    diagnostics: list[Diagnostic] = field(default_factory=list)
    fallback_lines: list[int] = field(default_factory=list)
    depends: list[tuple[str, str]] = field(default_factory=list)  # (included file, its file_stamp)
    missing: list[str] = field(default_factory=list)
    behavior: FileBehavior = field(default_factory=FileBehavior)
    loads: list[LoadedNodelet] = field(default_factory=list)
    plugin_loads: list[tuple[str, int]] = field(default_factory=list)  # (file, line): pluginlib classes created
    classes: list[str] = field(default_factory=list)  # a nodelet's class and the bases this file knows of
    calls: Sites = field(default_factory=dict)  # the handle and name arguments of its calls (callers.py)
    graph: CallGraph | None = None  # what its functions call (reach.py), for an executable's file
