"""The pipeline: index the workspace, interpret the configuration, extract nodes, link the system,
build facts."""

from __future__ import annotations

import os
import signal
import time
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from pathlib import Path

from archlog import budget, collector, sandbox
from archlog.diagnostics import Diagnostic, DiagnosticSink
from archlog.errors import ConfigError
from archlog.extract import parameter_library, registry
from archlog.extract.cpp.extract import CppEnvironment, extract_cpp
from archlog.extract.cpp.msg_headers import generated_headers
from archlog.extract.cpp.parameter_headers import parameter_headers
from archlog.extract.files import files_under
from archlog.extract.launch.model import LaunchConfig
from archlog.extract.launch.ros1 import LaunchInterpreter
from archlog.extract.python.node import extract_python
from archlog.extract.summary import NodeSummary
from archlog.extract.workspace.index import Workspace
from archlog.extract.workspace.packages import Executable, share_dirs
from archlog.facts.compose import compose
from archlog.facts.near_misses import add_near_names
from archlog.facts.parameters import add_param_near
from archlog.facts.patterns import add_name_fits
from archlog.facts.store import FactStore
from archlog.system.link import link
from archlog.system.named_plugins import named_plugins
from archlog.system.node_models import BUILTIN_DIR, load_node_models


@dataclass
class Analysis:
    workspace: Workspace
    config: LaunchConfig
    store: FactStore
    diagnostics: DiagnosticSink
    timings: dict[str, float] = field(default_factory=dict)
    policy: sandbox.Sandbox = field(default_factory=sandbox.current)  # what the run could read (reports too)


Progress = registry.Progress


def analyse(paths: list[Path], launches: list[str], args: dict[str, str], models: list[Path],
            near_threshold: float = 0.5, progress: Progress | None = None,
            env: dict[str, str] | None = None, limits: dict[str, int] | None = None,
            env_from_shell: bool = False) -> Analysis:
    """Recover the architecture of one system configuration into facts, reading only inside the
    analysed paths and package roots, seeing only the environment given in `env` (and the
    allow-list; with `env_from_shell`, the variables the input asks for from this process's
    environment too, each named in an env-from-shell note), and expanding within `limits` (see
    archlog.sandbox and archlog.budget)."""
    policy = sandbox.Sandbox(reading_roots(paths, launches, models), sandbox.machine_env(env), shell=env_from_shell)
    with sandbox.active(policy), budget.active(limits or {}):
        analysis = _analyse(paths, launches, args, models, near_threshold, progress)
    if policy.from_shell:
        where = str(resolve_launch(launches[0], analysis.workspace)) if launches else str(paths[0]) if paths else ""
        analysis.diagnostics.add(analysis.workspace.display(Path(where)) if where else "", 1, "env-from-shell",
                                 "read from this shell (--env-from-shell): " + ", ".join(sorted(policy.from_shell)))
    return analysis


def reading_roots(paths: list[Path], launches: list[str], models: list[Path]) -> tuple[Path, ...]:
    """Where a run may read: the analysed paths, files named on the command line, installed
    package share folders, the system include folders and archlog's own node models (resolved,
    symlinks followed). A file named on the command line that is a symlink does not make its
    target readable: the workspace may have replaced the file with a link to a secret."""
    given = [*paths, *models, *(Path(spec) for spec in launches if Path(spec).is_file())]
    system = [*share_dirs(), BUILTIN_DIR, Path("/usr/include"), Path("/usr/local/include"), Path("/usr/lib/llvm-14"),
              *Path("/opt/ros").glob("*/include")]
    named = [Path(os.path.realpath(p.parent)) / p.name if p.is_file() else Path(os.path.realpath(p)) for p in given]
    return tuple(dict.fromkeys([*named, *(Path(os.path.realpath(p)) for p in system)]))


def _analyse(paths: list[Path], launches: list[str], args: dict[str, str], models: list[Path],
             near_threshold: float, progress: Progress | None) -> Analysis:
    timings: dict[str, float] = {}
    clock = time.perf_counter()
    for path in paths:
        if not path.exists():
            raise ConfigError(f"path does not exist: {path}")
    diagnostics = DiagnosticSink()
    workspace = Workspace(paths, diagnostics)
    timings["workspace"] = _lap(clock)

    clock = time.perf_counter()
    launch_files = [resolve_launch(spec, workspace) for spec in launches]
    config = LaunchInterpreter(workspace, diagnostics).load(launch_files, args) if launch_files else None
    timings["launch"] = _lap(clock)

    clock = time.perf_counter()
    node_models = load_node_models(models, workspace, diagnostics)
    wanted = {n.kind for n in config.nodes} if config else None
    extracted = registry.extract(workspace, wanted, diagnostics, progress or (lambda _done, _total: None))
    for key, summary in extracted.items():
        exe = workspace.executable(*key)
        if exe is not None and exe.parameter_files:  # a copy: a summary may be cached
            extracted[key] = replace(summary, ports=list(summary.ports))
            parameter_library.add_declarations(extracted[key], exe.parameter_files, workspace.display, diagnostics)
    if config:
        extracted.update(_plugin_classes(config, extracted, workspace, diagnostics, progress))
    timings["extract"] = _lap(clock)

    clock = time.perf_counter()
    system = link(workspace, config, node_models, extracted, diagnostics)
    timings["link"] = _lap(clock)

    with collector.paused():
        clock = time.perf_counter()
        store = compose(system, diagnostics)
        timings["facts"] = _lap(clock)

        clock = time.perf_counter()
        add_near_names(store, near_threshold, diagnostics)
        add_param_near(store, near_threshold)
        add_name_fits(store)
        timings["near-miss"] = _lap(clock)
    return Analysis(workspace, system.config, store, diagnostics, timings)


def _plugin_classes(config: LaunchConfig, extracted: registry.Summaries, workspace: Workspace,
                    diagnostics: DiagnosticSink, progress: Progress | None) -> registry.Summaries:
    """The summaries of the pluginlib classes the nodes' parameters name (system/named_plugins.py),
    read like nodelets."""
    plugins = {plugin.kind for node in config.nodes for plugin in named_plugins(node, extracted.get(node.kind), workspace)
               if plugin.kind is not None} - extracted.keys()
    return registry.extract(workspace, plugins, diagnostics, progress or (lambda _done, _total: None)) if plugins else {}


def resolve_launch(spec: str, workspace: Workspace) -> Path:
    """A launch file given as a path, or as PKG/relative/path (or PKG/file name) like roslaunch."""
    path = Path(spec)
    if path.is_file():
        return Path(os.path.abspath(path))  # a symlink stays itself: the sandbox judges where it points
    pkg, _, rest = spec.partition("/")
    base = workspace.find(pkg)
    if base is not None and rest:
        if (base / rest).is_file():
            return base / rest
        matches = [p for p in files_under(base) if p.name == Path(rest).name]
        if matches:
            return matches[0]
    raise ConfigError(f"launch file not found: {spec} (give a path, or PKG/path inside the package)")


def _python(workspace: Workspace, diagnostics: DiagnosticSink) -> Callable[[Executable], NodeSummary]:
    """Python executables are read in this process (ast only)."""
    return lambda exe: extract_python(exe.sources[0], exe.package, exe.name, workspace.display(exe.sources[0]),
                                      diagnostics, workspace.display)


def _cpp(workspace: Workspace, diagnostics: DiagnosticSink) -> Callable[[Executable], _CppJob]:
    """C++ executables are parsed by libclang in worker processes, sharing one include environment."""
    env = CppEnvironment([d for p in workspace.packages.values() for d in [p.path / "include", *p.include_dirs]],
                         generated_headers(workspace, diagnostics), workspace.roots,
                         parameter_headers=parameter_headers(workspace))
    return lambda exe: _CppJob(exe.sources, {s: workspace.display(s) for s in exe.sources}, exe.package, exe.name,
                               env, exe.cls, sandbox.current(), dict(budget.current().limits), exe.linked)


CPP_JOB_CPU_SECONDS = 300
"""Most CPU time one executable's C++ may take (libclang has no budget of its own), counted in CPU
seconds so that a machine busy with other work does not cut a job short."""
CPP_JOB_WALL_SECONDS = 4 * CPP_JOB_CPU_SECONDS
"""The backstop for a job that stops using the CPU without ending."""


@dataclass(frozen=True)
class _CppJob:
    sources: list[Path]
    shown: dict[Path, str]
    package: str
    executable: str
    env: CppEnvironment
    cls: str | None = None
    policy: sandbox.Sandbox = field(default_factory=sandbox.current)
    limits: dict[str, int] = field(default_factory=dict)
    linked: list[Path] = field(default_factory=list)

    def __call__(self) -> tuple[NodeSummary, list[Diagnostic]]:
        sink = DiagnosticSink()
        signal.setitimer(signal.ITIMER_PROF, CPP_JOB_CPU_SECONDS)  # past either (SIGPROF, SIGALRM) the worker
        signal.alarm(CPP_JOB_WALL_SECONDS)  # dies: reported as a crash of this executable
        try:
            with sandbox.active(self.policy), budget.active(self.limits):
                summary = extract_cpp(self.sources, self.package, self.executable, self.env, self.shown, sink,
                                      self.cls, self.linked)
        finally:
            signal.setitimer(signal.ITIMER_PROF, 0)
            signal.alarm(0)
        return summary, sink.items

    def crashed(self, diagnostics: DiagnosticSink) -> None:
        diagnostics.add(next(iter(self.shown.values()), self.package), 1, "cpp-crash",
                        f"the C++ parser crashed on {self.package}/{self.executable}; its ROS calls are not "
                        "recovered", "error")


registry.register("python", registry.InputKind(start=_python))
registry.register("cpp", registry.InputKind(start_isolated=_cpp))


def _lap(start: float) -> float:
    return round(time.perf_counter() - start, 4)
