"""The input kinds: each language of node executables registers how its sources become a node
summary, and a run extracts every executable through the kind its language names."""

from __future__ import annotations

import os
import resource
from collections.abc import Callable
from concurrent.futures import ProcessPoolExecutor
from concurrent.futures.process import BrokenProcessPool
from dataclasses import dataclass
from typing import Protocol

from archlog.diagnostics import Diagnostic, DiagnosticSink
from archlog.extract.summary import NodeSummary
from archlog.extract.workspace.index import Workspace
from archlog.extract.workspace.packages import Executable

Summaries = dict[tuple[str, str], NodeSummary]
Progress = Callable[[int, int], None]
Found = tuple[NodeSummary, list[Diagnostic]]


class IsolatedJob(Protocol):
    """One executable's extraction, picklable, run in a worker process: its summary and diagnostics."""

    @property
    def package(self) -> str: ...

    @property
    def executable(self) -> str: ...

    def __call__(self) -> Found: ...

    def crashed(self, diagnostics: DiagnosticSink) -> None:
        """Report that the worker process died on this job."""


Start = Callable[[Workspace, DiagnosticSink], Callable[[Executable], NodeSummary]]
StartIsolated = Callable[[Workspace, DiagnosticSink], Callable[[Executable], IsolatedJob]]


@dataclass(frozen=True)
class InputKind:
    """How one language's executables are extracted: `start(workspace, diagnostics)` is called once
    per run, at the first executable of the language, and gives the extractor of one executable,
    run in this process; or `start_isolated` gives the job of one executable, run in a worker
    process so that a crash in a native parser costs that executable, not the run."""

    start: Start | None = None
    start_isolated: StartIsolated | None = None


INPUT_KINDS: dict[str, InputKind] = {}


def register(lang: str, kind: InputKind) -> None:
    """Make `lang` (an Executable's language) an input kind."""
    INPUT_KINDS[lang] = kind


def extract(workspace: Workspace, wanted: set[tuple[str, str]] | None, diagnostics: DiagnosticSink,
            progress: Progress) -> Summaries:
    """Summaries of the executables the configuration runs (all of them when `wanted` is None) whose
    language is an input kind, and of the nodelets they load into their own process (`wanted` may
    also name pluginlib classes, (package, C++ type): their code is read like a nodelet's);
    `progress(done, total)` is called as they finish."""
    summaries = _extract(workspace, wanted, diagnostics, progress)
    loaded = {kind for s in summaries.values() for n in s.loads if (kind := plugin_kind(n.plugin))} - summaries.keys()
    if loaded and wanted is not None:
        summaries.update(_extract(workspace, loaded, diagnostics, progress))
    return summaries


def plugin_kind(plugin: object) -> tuple[str, str] | None:
    """(package, Type) of a plugin name pkg/Type, as a launch file's `nodelet load` runs it."""
    if isinstance(plugin, str) and plugin.count("/") == 1 and all(plugin.split("/")):
        pkg, name = plugin.split("/")
        return pkg, name
    return None


def _extract(workspace: Workspace, wanted: set[tuple[str, str]] | None, diagnostics: DiagnosticSink,
             progress: Progress) -> Summaries:
    summaries: Summaries = {}
    inline: dict[str, Callable[[Executable], NodeSummary]] = {}
    isolated: dict[str, Callable[[Executable], IsolatedJob]] = {}
    jobs: list[IsolatedJob] = []
    aliases: dict[tuple[str, str], tuple[str, str]] = {}
    for package in workspace.packages.values():
        plugins = {id(c): c for c in package.plugin_classes.values()} if wanted is not None else {}
        for exe in [*package.executables.values(), *plugins.values()]:
            kind = INPUT_KINDS.get(exe.lang)
            if kind is None or wanted is not None and not wanted.intersection(exe.kinds):
                continue
            aliases.update((alias, exe.kinds[0]) for alias in exe.kinds[1:])
            if kind.start_isolated is not None:
                if exe.lang not in isolated:
                    isolated[exe.lang] = kind.start_isolated(workspace, diagnostics)
                jobs.append(isolated[exe.lang](exe))
            elif kind.start is not None:
                progress(len(summaries), -1)
                if exe.lang not in inline:
                    inline[exe.lang] = kind.start(workspace, diagnostics)
                summaries[(package.name, exe.name)] = inline[exe.lang](exe)
    done = len(summaries)
    for job, result in run_isolated(jobs, lambda n: progress(done + n, done + len(jobs))):
        if result is None:
            job.crashed(diagnostics)
            continue
        summary, found = result
        summaries[(job.package, job.executable)] = summary
        diagnostics.extend(found)
    summaries.update((alias, summaries[own]) for alias, own in aliases.items() if own in summaries)
    return summaries


WORKER_MEMORY = 4 << 30
"""Address space one worker may use (a native parser has no budget of its own): past it the
worker's allocations fail, and its executable is reported as a crash."""


def _cap_memory() -> None:
    soft, hard = resource.getrlimit(resource.RLIMIT_AS)
    cap = WORKER_MEMORY if soft == resource.RLIM_INFINITY else min(soft, WORKER_MEMORY)
    resource.setrlimit(resource.RLIMIT_AS, (cap, hard))


def run_isolated(jobs: list[IsolatedJob], finished: Callable[[int], None]
                 ) -> list[tuple[IsolatedJob, Found | None]]:
    """Run jobs in worker processes so that a crash in a native parser costs one executable, not the
    run. Jobs lost when a worker dies are retried one per process to find the one that crashes."""
    if not jobs:
        return []
    results: dict[int, Found | None] = {}
    with ProcessPoolExecutor(max_workers=min(len(jobs), os.cpu_count() or 1), initializer=_cap_memory) as pool:
        futures = {k: pool.submit(job) for k, job in enumerate(jobs)}
        for k, future in futures.items():
            try:
                results[k] = future.result()
                finished(len(results))
            except BrokenProcessPool:
                continue  # retried below, one job per process
    for k in [k for k in range(len(jobs)) if k not in results]:
        with ProcessPoolExecutor(max_workers=1, initializer=_cap_memory) as pool:
            try:
                results[k] = pool.submit(jobs[k]).result()
            except BrokenProcessPool:
                results[k] = None
    return [(job, results[k]) for k, job in enumerate(jobs)]
