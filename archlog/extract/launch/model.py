"""What both launch dialects build and share: the elements, node instances and configuration a
launch file yields, the errors of substitutions, and what the ROS 2 executor needs from its host."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Protocol

from archlog import budget, sandbox
from archlog.diagnostics import DiagnosticSink
from archlog.extract.workspace.index import Workspace

if TYPE_CHECKING:
    from archlog.extract.launch.conditions import Guard


class LaunchError(Exception):
    """An element roslaunch would reject."""


@dataclass(frozen=True)
class Element:
    """A launch element that facts can point at."""

    id: str
    file: str
    line: int


@dataclass
class LaunchNode:
    """A node instance declared by a launch file (or given by rosrun)."""

    elem: Element
    pkg: str
    type: str
    name: str
    namespace: str
    remaps: list[tuple[str, str, Element]] = field(default_factory=list)
    condition: str | None = None
    args: str = ""
    plugin: str | None = None
    manager: str | None = None
    declared: str = ""  # the name as declared (before __name/__ns in args); roslaunch checks these
    chain: tuple[Element, ...] = ()  # the <include> elements it was loaded through, outermost first
    # ROS 2: parameters as (node-name pattern, dotted name, value, element); the pattern is "" for
    # parameters given to this node directly, else a parameter file's node key ("/**", "/ns/talker")
    parameters: list[tuple[str, str, object, Element]] = field(default_factory=list)
    ros2: bool = False  # remaps then apply first-match-wins, as rcl does (roslaunch's last one wins)
    standalone: bool = False  # started by itself (no launch file): not known to run with the others
    name_unknown: bool = False  # its name is not known statically: the executable's name stands in for it
    # each undecided condition's guard (None for one that does not depend on one unknown argument alone)
    guards: tuple[Guard | None, ...] = ()
    # when every undecided condition has a guard: per unknown argument, the values it may run with
    when: dict[str, frozenset[str]] | None = None

    @property
    def kind(self) -> tuple[str, str]:
        """What runs: (package, executable), (package, Type) of a nodelet plugin pkg/Type, or
        (package, ns::Class) of a ROS 2 component."""
        if self.plugin and "::" in self.plugin:
            return self.pkg, self.plugin
        if self.plugin and "/" in self.plugin:
            pkg, plugin = self.plugin.split("/", 1)
            return pkg, plugin
        return self.pkg, self.type


@dataclass
class LaunchConfig:
    """The system configuration: node instances, parameter values, and every scope-level remap
    (resolved in its scope's namespace) so that one that reaches no node can be reported."""

    nodes: list[LaunchNode] = field(default_factory=list)
    params: dict[str, tuple[object, Element]] = field(default_factory=dict)
    # where the configuration sets parameters archlog cannot know (a parameter file or name not known
    # statically, an element skipped), and why
    params_unknown: list[tuple[Element, str]] = field(default_factory=list)
    scope_remaps: list[tuple[Element, str, str]] = field(default_factory=list)
    holes: list[tuple[str, int, str]] = field(default_factory=list)  # (file, line, why): parts not read


class SubstitutionError(Exception):
    """A substitution roslaunch rejects."""


class Unresolved(SubstitutionError):
    """A substitution that depends on the machine it runs on (an unset env var, a package that
    is not here, an arg whose value is itself unresolved)."""


class RefusedRead(Unresolved):
    """A file a launch file names that archlog will not read (outside the analysed paths, not a
    regular file, too large); `code` is the sandbox's diagnostic code. The message names the path."""

    def __init__(self, refused: sandbox.Refused) -> None:
        super().__init__(str(refused))
        self.code = refused.code


def read_file(path: Path | str, kind: str) -> str:
    """A file's text as a launch file reads it, under the sandbox (bad bytes become U+FFFD)."""
    try:
        return sandbox.read_text(path, kind)
    except sandbox.Refused as exc:
        raise RefusedRead(exc) from None


def unresolved_code(exc: Unresolved, default: str) -> str:
    """The diagnostic code for an unresolved value: the sandbox's code when a read was refused."""
    return exc.code if isinstance(exc, RefusedRead) else default


@dataclass(frozen=True)
class UnknownArg:
    """An arg whose value could not be resolved statically."""

    reason: str


def include_cycle(display: Callable[[Path], str], target: Path, file: Path, chain: tuple[Element, ...]) -> str | None:
    """When `target` is being loaded already (by `file` or the includes of `chain` that led to
    it), the files of the cycle an include of it would close, else None."""
    opened = [e.file for e in chain] + [display(file)]
    shown = display(target)
    return " -> ".join([*opened[opened.index(shown):], shown]) if shown in opened else None


class Nesting:
    """How many lists of elements are being loaded (a file, its groups, the files it includes),
    checked against the budget's depth before one more is entered."""

    def __init__(self) -> None:
        self.depth = 0

    @contextmanager
    def deeper(self) -> Iterator[None]:
        budget.current().check("depth", self.depth + 1)
        self.depth += 1
        try:
            yield
        finally:
            self.depth -= 1


class LaunchHost(Protocol):
    """What the ROS 2 executor needs from the interpreter it runs in: its workspace, diagnostics,
    configuration, element ids and path display."""

    workspace: Workspace
    diagnostics: DiagnosticSink
    config: LaunchConfig

    def display(self, path: Path) -> str: ...

    def element_at(self, file: Path, line: int) -> Element: ...

    def report_crossing(self, crossing: budget.Crossed) -> None: ...
