"""The pipeline: index the workspace, interpret the configuration, extract nodes, build facts."""

from __future__ import annotations

import os
import signal
import time
from concurrent.futures import ProcessPoolExecutor
from concurrent.futures.process import BrokenProcessPool
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

from archlog import budget, names, sandbox
from archlog.diagnostics import DiagnosticSink
from archlog.extract.controllers import controller_nodes
from archlog.extract.cpp.extract import CppEnvironment, extract_cpp
from archlog.extract.files import files_under
from archlog.extract.launch import Element, LaunchConfig, LaunchInterpreter, LaunchNode
from archlog.extract.messages import message_files
from archlog.extract.cpp.msg_headers import generated_headers
from archlog.extract.models import BUILTIN_DIR, load_models
from archlog.extract.python import extract_python
from archlog.extract.summary import NodeSummary
from archlog.extract.workspace import Workspace, share_dirs
from archlog.facts.compose import compose, rosrun_config
from archlog.facts.instances import complete_instances
from archlog.facts.store import FactStore


class ConfigError(Exception):
    """A usage or configuration error (exit status 2)."""


@dataclass
class Analysis:
    workspace: Workspace
    config: LaunchConfig
    store: FactStore
    diagnostics: DiagnosticSink
    timings: dict[str, float] = field(default_factory=dict)
    policy: sandbox.Sandbox = field(default_factory=sandbox.current)  # what the run could read (reports too)


Progress = Callable[[int, int], None]


def analyse(paths: list[Path], launches: list[str], args: dict[str, str], models: list[Path],
            near_threshold: float = 0.5, progress: Progress | None = None,
            env: dict[str, str] | None = None, limits: dict[str, int] | None = None) -> Analysis:
    """Recover the architecture of one system configuration into facts, reading only inside the
    analysed paths and package roots, seeing only the environment given in `env` (and the
    allow-list), and expanding within `limits` (see archlog.sandbox and archlog.budget)."""
    policy = sandbox.Sandbox(reading_roots(paths, launches, models), sandbox.machine_env(env))
    with sandbox.active(policy), budget.active(limits or {}):
        return _analyse(paths, launches, args, models, near_threshold, progress)


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
    builtin, user, externals = _models(models, workspace, diagnostics)
    wanted = {n.kind for n in config.nodes} if config else None
    summaries = dict(builtin)
    summaries.update(_extract(workspace, wanted, diagnostics, progress or (lambda _done, _total: None)))
    summaries.update(user)
    if config is None:
        config = rosrun_config({k: v for k, v in summaries.items() if k[0] in workspace.packages},
                               workspace, diagnostics)
    complete_instances(config, summaries, diagnostics)
    config.nodes.extend(controller_nodes(config, diagnostics))
    for summary, instance, elem in externals:
        summaries[(summary.package, summary.executable)] = summary
        config.nodes.append(LaunchNode(elem, summary.package, summary.executable, names.join("/", instance),
                                       names.namespace_of(names.join("/", instance))))
    timings["extract"] = _lap(clock)

    clock = time.perf_counter()
    store = compose(workspace, config, summaries, message_files(workspace), diagnostics, near_threshold)
    timings["facts"] = _lap(clock)
    return Analysis(workspace, config, store, diagnostics, timings)


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


def _extract(workspace: Workspace, wanted: set[tuple[str, str]] | None, diagnostics: DiagnosticSink,
             progress: Progress) -> dict[tuple[str, str], NodeSummary]:
    """Summaries of the executables the configuration runs (all of them without a launch file);
    `progress(done, total)` is called as they finish."""
    summaries = {}
    cpp_jobs = []
    env: CppEnvironment | None = None
    for package in workspace.packages.values():
        for exe in package.executables.values():
            if wanted is not None and (package.name, exe.name) not in wanted:
                continue
            if exe.lang == "other":
                continue
            if exe.lang == "python":
                progress(len(summaries), -1)
                summaries[(package.name, exe.name)] = extract_python(
                    exe.sources[0], package.name, exe.name, workspace.display(exe.sources[0]), diagnostics)
            else:
                env = env or CppEnvironment(
                    [d for p in workspace.packages.values() for d in [p.path / "include", *p.include_dirs]],
                    generated_headers(workspace, diagnostics), workspace.roots)
                shown = {s: workspace.display(s) for s in exe.sources}
                cpp_jobs.append(_CppJob(exe.sources, shown, package.name, exe.name, env, exe.cls,
                                        sandbox.current(), dict(budget.current().limits)))
    done = len(summaries)
    for job, result in _run_isolated(cpp_jobs, lambda n: progress(done + n, done + len(cpp_jobs))):
        if result is None:
            diagnostics.add(next(iter(job.shown.values()), job.package), 1, "cpp-crash",
                            f"the C++ parser crashed on {job.package}/{job.executable}; its ROS calls are not "
                            "recovered", "error")
            continue
        summary, found = result
        summaries[(job.package, job.executable)] = summary
        for diag in found:
            diagnostics.add(diag.file, diag.line, diag.code, diag.message, diag.severity, diag.column)
    return summaries


CPP_JOB_SECONDS = 300
"""Longest one executable's C++ may take (libclang has no budget of its own)."""


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

    def __call__(self) -> tuple[NodeSummary, list]:
        sink = DiagnosticSink()
        signal.alarm(CPP_JOB_SECONDS)  # past it the worker dies: reported as a crash of this executable
        try:
            with sandbox.active(self.policy), budget.active(self.limits):
                summary = extract_cpp(self.sources, self.package, self.executable, self.env, self.shown, sink,
                                      self.cls)
        finally:
            signal.alarm(0)
        return summary, sink.items


def _run_isolated(jobs: list[_CppJob], finished: Callable[[int], None]
                  ) -> list[tuple[_CppJob, tuple[NodeSummary, list] | None]]:
    """Run jobs in worker processes so that a crash in libclang costs one executable, not the run.
    Jobs lost when a worker dies are retried one per process to find the one that crashes."""
    if not jobs:
        return []
    results: dict[int, tuple[NodeSummary, list] | None] = {}
    with ProcessPoolExecutor(max_workers=min(len(jobs), os.cpu_count() or 1)) as pool:
        futures = {k: pool.submit(job) for k, job in enumerate(jobs)}
        for k, future in futures.items():
            try:
                results[k] = future.result()
                finished(len(results))
            except BrokenProcessPool:
                continue  # retried below, one job per process
    for k in [k for k in range(len(jobs)) if k not in results]:
        with ProcessPoolExecutor(max_workers=1) as pool:
            try:
                results[k] = pool.submit(jobs[k]).result()
            except BrokenProcessPool:
                results[k] = None
    return [(job, results[k]) for k, job in enumerate(jobs)]


Summaries = dict[tuple[str, str], NodeSummary]


def _models(paths: list[Path], workspace: Workspace, diagnostics: DiagnosticSink
            ) -> tuple[Summaries, Summaries, list[tuple[NodeSummary, str, Element]]]:
    """Shipped models, the user's models, and external instances declared by models."""
    builtin: Summaries = {}
    user: Summaries = {}
    externals: list[tuple[NodeSummary, str, Element]] = []
    files = [(p, builtin) for p in sorted(BUILTIN_DIR.glob("*.yaml"))] + [(p, user) for p in paths]
    for index, (path, target) in enumerate(files, 1):
        if not path.is_file():
            raise ConfigError(f"model file not found: {path}")
        shown = workspace.display(path)
        for summary, instance in load_models(path, shown, diagnostics):
            if instance:
                line = summary.ports[0].line - 1 if summary.ports else 1
                externals.append((summary, instance, Element(f"m{index:03d}{len(externals):03d}", shown, max(line, 1))))
            else:
                target[(summary.package, summary.executable)] = summary
    return builtin, user, externals


def _lap(start: float) -> float:
    return round(time.perf_counter() - start, 4)
