"""roscpp and rclcpp nodes: parse C++ with libclang and hand each file to the walker (roscpp.py).

No compile database is needed: include paths come from the workspace (include/ folders and
include_directories()), headers generated for the workspace's own messages, /opt/ros/*/include
and /usr/include. ros/ros.h is precompiled once per machine (a PCH in the cache folder), and
each file's result is stored in an on-disk cache keyed by its content and every flag.

Headers that are not installed get stand-ins: ROS 1 message headers (stubs.py), and for
ROS 2 code the client libraries and interfaces (stubs.py), searched first. Errors that come
from what a stand-in lacks are not the code's fault: they only make the walker read the lines
it lost from the tokens.
"""

from __future__ import annotations

import glob
import json
import os
import re
import shlex
import shutil
import subprocess
import tempfile
from collections.abc import Callable, Collection
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path

import clang.cindex as ci

from archlog import sandbox
from archlog.diagnostics import Diagnostic, DiagnosticSink
from archlog.extract.cpp.behavior import FileBehavior, link_files
from archlog.extract.cpp.cache import ResultCache, cache_dir, file_stamp, key
from archlog.extract.cpp.callers import merged_sites, settled_loads, settled_ports
from archlog.extract.cpp.macros import MACRO_TOKENS, Macro, defines, macro_bomb, nested_calls
from archlog.extract.cpp.reach import reached
from archlog.extract.cpp.result import FileResult
from archlog.extract.cpp.ros1_stand_ins import MESSAGE_INCLUDE, ros1_library, ros1_stand_in_dir
from archlog.extract.cpp.roscpp import walk
from archlog.extract.cpp.stubs import (
    API_DIR,
    DUAL,
    INTERFACE_INCLUDE,
    Interfaces,
    is_ros2,
    library_for,
    library_interfaces,
    spelled_types,
    stand_in_dir,
)
from archlog.extract.files import files_under, unreadable
from archlog.extract.summary import NodeSummary
from archlog.extract.workspace.packages import manifests, pruned

_KEEP_GOING = 0x200
SOURCE_CAP = 512 << 10
"""Largest C++ source parsed (bytes): libclang and the walk take ~13 s a MiB, and no node's file
is near it (headers it includes are not capped: only their code a node calls is walked)."""
_NOT_FOUND = re.compile(r"'([^']+)' file not found")
_HEADER_SUFFIXES = {".h", ".hh", ".hpp", ".hxx", ".cuh"}


@lru_cache(maxsize=1)
def resource_dir() -> str | None:
    """clang's builtin headers, which the PyPI libclang wheel does not ship."""
    clang = shutil.which("clang") or shutil.which("clang-14")
    if clang:
        out = subprocess.run([clang, "-print-resource-dir"], capture_output=True, text=True, check=False)
        if out.returncode == 0 and Path(out.stdout.strip(), "include").is_dir():
            return out.stdout.strip()
    found = sorted(glob.glob("/usr/lib/llvm-*/lib/clang/*/include/stddef.h"), reverse=True)
    return str(Path(found[0]).parent.parent) if found else None


@dataclass
class CppEnvironment:
    """Compiler flags shared by every file of a run, and the fingerprint of what they read."""

    workspace_includes: list[Path]
    generated: Path | None = None
    roots: list[Path] = field(default_factory=list)
    args: list[str] = field(default_factory=list)
    per_file: dict[str, list[str]] = field(default_factory=dict)
    pch: Path | None = None
    fingerprint: str = ""
    interfaces: Interfaces = field(default_factory=Interfaces)
    refused: list[str] = field(default_factory=list)  # workspace files clang must never read
    parameter_headers: Path | None = None  # stand-ins of generate_parameter_library headers (parameter_headers.py)
    listings: dict[str, frozenset[str]] = field(default_factory=dict)  # folder: its entries, listed once per job

    def __post_init__(self) -> None:
        system = sorted(glob.glob("/opt/ros/*/include")) + ["/usr/include"] + _nested_include_roots() + \
            [d for d in ("/usr/include/eigen3", "/usr/include/opencv4") if Path(d).is_dir()]
        includes = [str(p) for p in self.workspace_includes if p.is_dir() and sandbox.current().inside(p)]
        includes += [str(d) for d in (self.generated, self.parameter_headers) if d]
        self.args = ["-x", "c++", "-std=c++17", "-Wno-everything", "-ferror-limit=0",
                     *(f"-I{d}" for d in includes + system)]
        rdir = resource_dir()
        if rdir:
            self.args += ["-resource-dir", rdir]
        self.pch = _ros_pch(system, rdir)
        self.per_file = _compile_commands(self.roots)
        self.interfaces = Interfaces.index(m.parent for root in self.roots for m in manifests(root))
        self.refused = _refused_includes([str(p) for root in self.roots for p in files_under(root, pruned)])
        self.fingerprint = key(json.dumps(self.parse_args()), *map(str, self.roots),  # roots: whose headers are read
                               *_tree_stamp(self.workspace_includes), *self.interfaces.stamp(), _stand_in_stamp())

    def parse_args(self, source: Path | None = None) -> list[str]:
        pch = ["-include-pch", str(self.pch), "-Xclang", "-fno-validate-pch"] if self.pch else []
        return self.args + self.file_args(source) + pch

    def file_args(self, source: Path | None) -> list[str]:
        """Flags a compile database gives for this file (include paths, defines, standard)."""
        return self.per_file.get(os.path.realpath(source), []) if source is not None else []

    def folders(self, source: Path | None = None) -> list[Path]:
        """The include folders a file is parsed with (its compile database's first)."""
        return [Path(a[2:]) for a in self.file_args(source) + self.args if a.startswith("-I")]

    def find(self, name: str, folders: list[Path]) -> Path | None:
        """Where an include resolves; a ROS 1 header of a package that ROS 2 has under the same
        include names (tf2_ros, message_filters...) does not count for ROS 2 code."""
        dual = name.split("/", 1)[0] in DUAL
        return next((folder / name for folder in folders if self.may_hold(folder, name) and (folder / name).is_file()
                     and not (dual and _ros1_system(folder))), None)

    def may_hold(self, folder: Path, name: str) -> bool:
        """Whether `folder/name` can exist: the name's first part is an entry of the folder (each
        folder listed once per executable's job, instead of a stat per folder and include);
        `.`, `..` and absolute names are not judged."""
        first = name.split("/", 1)[0]
        if first in ("", ".", ".."):
            return True
        where = str(folder)
        if where not in self.listings:
            try:
                self.listings[where] = frozenset(os.listdir(where))
            except OSError:
                self.listings[where] = frozenset()
        return first in self.listings[where]


def extract_cpp(sources: list[Path], package: str, executable: str, env: CppEnvironment,
                shown: dict[Path, str], diagnostics: DiagnosticSink, cls: str | None = None,
                linked: Collection[Path] = ()) -> NodeSummary:
    """The summary of one executable (or of one nodelet class): every source file read, from the
    cache when unchanged. A nodelet's files are read after the one that names its class, with the
    base classes found there (their methods, defined in other files of the library, are the node's
    code too); a file read before more of them were known is read again. The ports of `linked`
    sources (its libraries') count only when the executable's own code reaches them (reach.py)."""
    summary = NodeSummary(package, executable, "cpp")
    reader = _Reader(env, shown, diagnostics, summary, graphs=bool(linked))
    if cls is not None:
        last = cls.rsplit("::", 1)[-1]
        sources = sorted(sources, key=lambda s: re.search(rf"\b{re.escape(last)}\b", _text(s)) is None)
    results: dict[Path, tuple[FileResult, str | None]] = {}
    pending = list(sources)
    while pending:
        source = pending.pop(0)
        result = reader.read(source, cls)
        if result is None:
            continue
        results[source] = (result, cls)
        if cls is not None and len(result.classes) > len(cls.split("|")):
            cls = "|".join(result.classes)  # files read before the class's bases were known: again
            pending += [s for s, (_r, read_as) in results.items() if read_as != cls and s not in pending]
    behaviors: list[FileBehavior] = []
    running = _reached_code(sources, linked, {s: r for s, (r, _cls) in results.items()})
    for source in sources:
        if source in results:
            _merge(summary, results[source][0], diagnostics, running if source in linked else None)
            behaviors.append(results[source][0].behavior)
    sites = merged_sites([result.calls for result, _cls in results.values()])
    summary.ports, summary.loads = settled_ports(summary.ports, sites), settled_loads(summary.loads, sites)
    summary.publishes, summary.writes = link_files(behaviors)
    _settle_behavior(summary)
    return summary


@dataclass
class _Reader:
    """Reads one source file for extract_cpp (from the cache when unchanged); a file that cannot be
    read is a diagnostic and makes the summary incomplete."""

    env: CppEnvironment
    shown: dict[Path, str]
    diagnostics: DiagnosticSink
    summary: NodeSummary
    graphs: bool = False  # each file's call graph too (an executable linking libraries: reach.py)
    cache: ResultCache = field(default_factory=lambda: ResultCache("cpp"))
    index: ci.Index | None = None

    def read(self, source: Path, cls: str | None) -> FileResult | None:
        name = self.shown.get(source, str(source))
        refused = unreadable(source, "source")
        if refused is not None:
            missing = refused.code == "missing"
            message = "source file listed in CMakeLists.txt does not exist" if missing else f"not read: {refused}"
            self.diagnostics.add(name, 1, "cpp-missing" if missing else refused.code, message, "error")
            self.summary.incomplete = self.summary.incomplete or f"{name}: {'missing' if missing else 'not read'}"
            return None
        try:
            data = sandbox.read_bytes(source, "source")
        except sandbox.Refused as exc:  # changed since it was checked
            self.diagnostics.add(name, 1, exc.code, f"not read: {exc}", "error")
            return None
        if len(data) > SOURCE_CAP:
            self.diagnostics.add(name, 1, "too-large", f"{len(data)} bytes, over the {SOURCE_CAP}-byte cap for C++ "
                                 "sources; its ROS calls are not recovered", "error")
            self.summary.incomplete = self.summary.incomplete or f"{name}: too large to read"
            return None
        cache_key = key(self.env.fingerprint, name, cls or "", " ".join(self.env.file_args(source)), data,
                        "graph" if self.graphs else "")
        result = self.cache.get(cache_key)
        if not isinstance(result, FileResult) or not _still_valid(result, self.env):
            self.index = self.index or ci.Index.create()
            result = _parse_guarded(self.index, source, name, self.env, cls, self.graphs)
            self.cache.put(cache_key, result)
        return result


def _text(source: Path) -> str:
    try:
        return sandbox.read_text(source, "source")
    except sandbox.Refused:  # reported when the file is read
        return ""


def _settle_behavior(summary: NodeSummary) -> None:
    """A call some file knows how it is reached is not also reached in an unknown way (a
    header's code read with several files); only the writes of variables some publish call
    depends on count."""
    known = {(p.file, p.line) for p in summary.publishes if p.trigger != "unknown"}
    summary.publishes = [p for p in summary.publishes if p.trigger != "unknown" or (p.file, p.line) not in known]
    guarded = {g.var for p in summary.publishes for g in p.guards}
    summary.writes = [w for w in summary.writes if w.var in guarded]


def _parse_guarded(index: ci.Index, source: Path, shown: str, env: CppEnvironment, cls: str | None,
                   graph: bool = False) -> FileResult:
    """`_parse`, with the walk's running out of memory or depth an error diagnostic."""
    try:
        return _parse(index, source, shown, env, cls, graph)
    except (MemoryError, RecursionError) as exc:
        return _failed(shown, 1, "cpp-walk", f"the walk over this file's syntax tree ran out of "
                       f"{'memory' if isinstance(exc, MemoryError) else 'depth'}; its ROS calls are not recovered")


def _failed(shown: str, line: int, code: str, message: str) -> FileResult:
    result = FileResult(incomplete=f"{shown}: not read")
    result.diagnostics.append(Diagnostic(shown, line, code, message, "error"))
    return result


def _parse(index: ci.Index, source: Path, shown: str, env: CppEnvironment, cls: str | None, graph: bool) -> FileResult:
    try:
        scan = _scan(source, env)
        if scan.macro_bomb is not None:
            file, at, macro = scan.macro_bomb
            return _failed(shown, at if file == source else 1, "cpp-macro",
                           f"macro {macro} ({file.name}:{at}) expands to more than {MACRO_TOKENS} tokens; "
                           "the file is not parsed")
        tu, stand_ins = _parse_confined(index, source, env, scan)
    except ci.TranslationUnitLoadError as exc:
        result = FileResult()
        result.diagnostics.append(Diagnostic(shown, 1, "cpp-parse", f"libclang could not parse this file: {exc}",
                                             "error"))
        result.incomplete = f"{shown}: could not be parsed"
        return result
    everywhere = [d for d in tu.diagnostics if d.severity >= ci.Diagnostic.Error and not _builtin_header(d)]
    gaps = [d for d in everywhere if stand_ins and _stand_in_gap(d, stand_ins)]
    genuine = [d for d in everywhere if d not in gaps and not (gaps and _cascade(d, gaps, source))]
    errors = [d for d in genuine if d.location.file and Path(d.location.file.name) == source]
    result = walk(tu, source, shown, incomplete_ast=bool(everywhere), cls=cls, ros2=scan.ros2, graph=graph,
                  workspace=tuple(str(root.resolve()) for root in env.roots))
    result.depends = [(inc.include.name, file_stamp(inc.include.name)) for inc in tu.get_includes()]
    result.diagnostics += _ros1_stand_in_note(tu, source, shown, stand_ins) if not scan.ros2 else []
    result.diagnostics += _blocked_includes(tu, source, shown, scan)
    result.missing = [m.group(1) for d in tu.diagnostics if (m := _NOT_FOUND.search(d.spelling))]
    result.missing += [n for n in scan.missing + scan.dual if n not in result.missing]
    if errors:
        first = errors[0]
        result.diagnostics.append(Diagnostic(shown, first.location.line, "cpp-compile",
                                             f"C++ does not compile here ({first.spelling}); calls were also read "
                                             "from the tokens", "warning"))
        if result.fallback_lines:
            result.incomplete = f"{shown}:{first.location.line}: does not compile"
    elif result.fallback_lines and genuine:  # the code compiles, what it includes does not
        first, line = genuine[0], min(result.fallback_lines)
        where = f"{Path(first.location.file.name).name}:{first.location.line}: " if first.location.file else ""
        result.diagnostics.append(Diagnostic(shown, line, "cpp-compile",
                                             f"C++ does not compile ({where}{first.spelling}); calls here were read "
                                             "from the tokens", "warning"))
        result.incomplete = f"{shown}:{line}: read from the tokens"
    elif result.fallback_lines:
        own = [d for d in gaps if d.location.file and Path(d.location.file.name) == source]
        first = next((d for d in own if d.location.line in result.fallback_lines), (own or gaps)[0])
        line = first.location.line if own else min(result.fallback_lines)
        result.diagnostics.append(Diagnostic(shown, line, "cpp-stand-in",
                                             f"archlog's stand-in ROS {2 if scan.ros2 else 1} headers lack what this line uses "
                                             f"({first.spelling}); its calls were read from the tokens", "note"))
        result.incomplete = f"{shown}:{line}: read from the tokens"
    return result


def _parse_confined(index: ci.Index, source: Path, env: CppEnvironment,
                    scan: _Scan) -> tuple[ci.TranslationUnit, list[str]]:
    """The unit parsed with every file outside the reading roots (or not a regular file) it
    includes seen empty by clang: those the scan found beforehand, then any the unit still
    included (through a macro, say), parsed again without them."""
    for _attempt in range(3):
        tu, stand_ins = (_parse_ros2 if scan.ros2 else _parse_ros1)(index, source, env, scan)
        more = [name for inc in tu.get_includes() if not scan.blocks(name := inc.include.name)
                and not _own(name) and unreadable(name, "source") is not None]
        if not more:
            return tu, stand_ins
        scan.blocked += list(dict.fromkeys(more))
    raise ci.TranslationUnitLoadError(f"it includes files outside the analysed paths: {', '.join(more)}")


def _own(path: Path | str) -> bool:
    """Headers archlog supplies (stand-ins, generated message headers, precompiled headers) and
    clang's builtin ones."""
    return str(path).startswith((str(cache_dir()), str(API_DIR), resource_dir() or str(API_DIR)))


def _ros1_stand_in_note(tu: ci.TranslationUnit, source: Path, shown: str, stand_ins: list[str]) -> list[Diagnostic]:
    """A note when ROS 1 library headers were stand-ins, at the line of the source that includes
    the first of them (directly or through its headers), naming it."""
    forwarders = [inc for inc in tu.get_includes() if stand_ins and inc.include.name.startswith(stand_ins[0])
                  and ros1_library(str(Path(inc.include.name).relative_to(stand_ins[0])))]
    if not forwarders:
        return []
    first = min(forwarders, key=lambda inc: inc.depth)  # the source's own include, if it has one
    line = first.location.line if first.source.name == str(source) else 1
    name = Path(first.include.name).relative_to(stand_ins[0])
    return [Diagnostic(shown, line, "cpp-ros1-stand-in", f"{name} is not installed: this file is read with "
                       "archlog's stand-in ROS 1 headers", "note")]


def _blocked_includes(tu: ci.TranslationUnit, source: Path, shown: str, scan: _Scan) -> list[Diagnostic]:
    """A diagnostic for each file the unit includes that clang was given empty, at the line of
    the source that includes it (directly or through its headers)."""
    found = []
    for inc in tu.get_includes():
        name = inc.include.name
        if scan.blocks(name) and (refused := unreadable(name, "source")) is not None:
            line = inc.location.line if inc.source.name == str(source) else 1
            found.append(Diagnostic(shown, line, refused.code, f"#include not read: {refused}", "warning"))
    return list(dict.fromkeys(found))


def _parse_ros1(index: ci.Index, source: Path, env: CppEnvironment,
                scan: _Scan) -> tuple[ci.TranslationUnit, list[str]]:
    """ROS 1 code: with ros/ros.h precompiled when installed, and stand-ins for the library and
    message headers that are not. Returns the unit and the stand-in folder used."""
    folders = env.folders(source)

    def exists(name: str) -> bool:
        return env.find(name, folders) is not None

    def attempt(wanted: list[str]) -> tuple[ci.TranslationUnit, list[str]]:
        folder = ros1_stand_in_dir(wanted, env.interfaces, exists)
        used = [str(folder), str(API_DIR)] if folder else []
        extra = [f"-I{f}" for f in used]
        return _load(index, source, env.parse_args(source) + extra, env.args + env.file_args(source) + extra,
                     scan.unsaved), used

    return _with_stand_ins(list(scan.missing), attempt, lambda n: bool(ros1_library(n) or MESSAGE_INCLUDE.match(n)))


def _parse_ros2(index: ci.Index, source: Path, env: CppEnvironment,
                scan: _Scan) -> tuple[ci.TranslationUnit, list[str]]:
    """ROS 2 code: stand-ins for the client libraries and interfaces that are not installed,
    searched before every other folder. Returns the unit and the stand-in folders used."""
    folders = env.folders(source)
    wanted = scan.missing + scan.dual

    def exists(name: str) -> bool:
        return env.find(name, folders) is not None

    def attempt(wanted: list[str]) -> tuple[ci.TranslationUnit, list[str]]:
        folder = stand_in_dir(wanted, scan.spellings, env.interfaces, exists)
        used = ([str(folder)] if folder else []) + [str(API_DIR)]
        stand_in_rclcpp = any(library_for(n) for n in wanted) and \
            not any(exists(n) for n in ["rclcpp/rclcpp.hpp", *library_interfaces("rclcpp")])
        pch = _rclcpp_pch() if stand_in_rclcpp else None
        return index.parse(str(source), args=[f"-I{f}" for f in used] + env.args + env.file_args(source)
                           + (["-include-pch", str(pch), "-Xclang", "-fno-validate-pch"] if pch else []),
                           unsaved_files=scan.unsaved, options=_KEEP_GOING), used

    return _with_stand_ins(wanted, attempt, lambda n: bool(library_for(n) or INTERFACE_INCLUDE.match(n)))


def _with_stand_ins(wanted: list[str], attempt: Callable[[list[str]], tuple[ci.TranslationUnit, list[str]]],
                    stands_in: Callable[[str], bool]) -> tuple[ci.TranslationUnit, list[str]]:
    """The unit parsed with stand-ins for the `wanted` includes (and the stand-in folders used); once
    more with the headers clang did not find that have stand-ins (included by an installed header,
    found only while parsing)."""
    tu, used = attempt(wanted)
    more = [m.group(1) for d in tu.diagnostics if (m := _NOT_FOUND.search(d.spelling))
            and stands_in(m.group(1)) and m.group(1) not in wanted]
    return attempt(wanted + list(dict.fromkeys(more))) if more else (tu, used)


def is_ros2_source(source: Path, env: CppEnvironment) -> bool:
    """ROS 2 code: the file or a workspace header it includes uses rclcpp or ROS 2 interfaces."""
    return _scan(source, env).ros2


@dataclass
class _Scan:
    """A file's includes, followed through the workspace's headers: those not found, the ROS 1
    headers of packages ROS 2 also has, and whether it is ROS 2 code."""

    missing: list[str]
    dual: list[str]
    spellings: set[str]
    ros2: bool
    macro_bomb: tuple[Path, int, str] | None = None  # (file, line, name) of a macro expanding too far
    blocked: list[str] = field(default_factory=list)  # files clang must not read (given empty)

    @property
    def unsaved(self) -> list[tuple[str, str]]:
        return [(path, "") for path in self.blocked]

    def blocks(self, path: str) -> bool:
        """Whether clang was given `path` empty (under any name of the file)."""
        return os.path.realpath(path) in {os.path.realpath(b) for b in self.blocked}


def _scan(source: Path, env: CppEnvironment) -> _Scan:
    folders = env.folders(source)
    queue, seen, texts, read = [source], {source}, [], []
    missing: list[str] = []
    dual: list[str] = []
    args = env.file_args(source)
    blocked = env.refused + _refused_includes([word for flag, word in zip(args, args[1:]) if flag == "-include"])
    macros: dict[str, Macro] = {}
    while queue and len(seen) < 400:
        path = queue.pop(0)
        try:
            text = path.read_text(errors="replace") if _own(path) else sandbox.read_text(path, "source")
        except sandbox.Refused:  # a header too large: clang sees it empty
            blocked.append(str(path))
            continue
        texts.append(text)
        dirs = [path.parent] + folders
        blocked += _refused_includes([str(folder / name) for name in _named_files(text) for folder in dirs
                                      if env.may_hold(folder, name)])
        read.append((path, text))
        macros.update(defines(path, text))
        for name in _INCLUDE.findall(text):
            found = env.find(name, dirs)
            if str(found) in blocked or found is None and any(str(folder / name) in blocked for folder in dirs
                                                                  if env.may_hold(folder, name)):
                continue
            if found is None:
                ros1 = name.split("/", 1)[0] in DUAL and any((f / name).is_file() for f in folders if _ros1_system(f))
                (dual if ros1 else missing).append(name)
            elif not str(found).startswith(("/usr/", "/opt/")) and found not in seen:
                seen.add(found)
                queue.append(found)
    return _Scan(list(dict.fromkeys(missing)), list(dict.fromkeys(dual)), spelled_types(texts),
                 any(is_ros2(t) for t in texts), macro_bomb(macros) or nested_calls(read, macros),
                 list(dict.fromkeys(blocked)))


_ANY_INCLUDE = re.compile(r'^\s*#\s*(?:include|include_next|import)\s*[<"]([^>"\n]+)[>"]', re.M)


def _named_files(text: str) -> list[str]:
    """The files a C++ text may make clang include that may lie outside the workspace: the names
    its #include lines spell, and every absolute or `..` path in it (a macro may hand one to an
    #include, here or in a header). Files inside it are in CppEnvironment.refused."""
    words = [w for w in re.findall(r"[\w./+-]*\w[\w./+-]*", text) if w.startswith("/") or ".." in w]
    return list(dict.fromkeys(_ANY_INCLUDE.findall(text) + words))


def _refused_includes(candidates: list[str]) -> list[str]:
    """The candidate paths of an include (and -include'd files) that exist but that the sandbox
    will not read: outside the reading roots, symlinked out, devices, FIFOs, folders."""
    return [p for p in candidates if os.path.lexists(p) and not _own(p) and unreadable(p, "source") is not None]


_STAND_IN_NAME = re.compile(r"\b(?:rclcpp\w*|rmw|rcl|tf2_ros|tf2|image_transport|message_filters|diagnostic_updater|"
                            r"\w+::(?:msg|srv|action))::|'(?:rclcpp\w*|rmw|tf2_ros|image_transport|message_filters)'|"
                            r"\bRCLCPP_|\brmw_|\brcl_")


def _stand_in_gap(diag: ci.Diagnostic, folders: list[str]) -> bool:
    """An error caused by what a stand-in header does not declare, not by the code."""
    if _NOT_FOUND.search(diag.spelling):
        return False
    notes = [c.location.file.name for c in diag.children if c.location.file is not None]
    return any(note.startswith(folder) for note in notes for folder in folders) or \
        bool(_STAND_IN_NAME.search(diag.spelling))


_UNDECLARED = re.compile(r"use of undeclared identifier '(\w+)'")


def _cascade(diag: ci.Diagnostic, gaps: list[ci.Diagnostic], source: Path) -> bool:
    """An identifier that is undeclared because its declaration was a stand-in gap."""
    match = _UNDECLARED.search(diag.spelling)
    if match is None:
        return False
    lines = sandbox.read_text(source, "source").splitlines()
    return any(0 < g.location.line <= len(lines) and re.search(rf"\b{match.group(1)}\b", lines[g.location.line - 1])
               for g in gaps)


def _builtin_header(diag: ci.Diagnostic) -> bool:
    """An error in clang's builtin headers (emmintrin.h...): those of the installed clang, which
    the libclang wheel may be newer than (its intrinsics are spelled differently). Only those
    headers' inline bodies break, not the code that includes them."""
    rdir = resource_dir()
    return rdir is not None and diag.location.file is not None and diag.location.file.name.startswith(rdir)


def _ros1_system(folder: Path) -> bool:
    """Debian's ROS 1 headers (/usr/include and its nested package folders)."""
    return str(folder) == "/usr/include" or str(folder.parent) == "/usr/include"


@lru_cache(maxsize=1)
def _stand_in_stamp() -> str:
    """The content of the library stand-ins, so that cached results do not outlive a change."""
    return key(*[p.read_bytes() for p in sorted(API_DIR.rglob("*.h*"))])


_KEPT_FLAGS = ("-I", "-D", "-U", "-isystem", "-std=", "-include")


def _compile_commands(roots: list[Path]) -> dict[str, list[str]]:
    """Per-file flags from build/compile_commands.json (catkin/colcon with CMAKE_EXPORT_COMPILE_COMMANDS)."""
    flags: dict[str, list[str]] = {}
    for root in roots:
        for database in (root / "build" / "compile_commands.json", root / "compile_commands.json"):
            try:
                entries = json.loads(sandbox.read_text(database, "build"))
            except (sandbox.Refused, ValueError, RecursionError):
                continue
            for entry in entries if isinstance(entries, list) else []:
                words = entry.get("arguments") or shlex.split(entry.get("command", ""))
                directory = Path(entry.get("directory", root))
                kept, take_next = [], False
                for word in words[1:]:
                    if take_next:
                        kept.append(word)
                        take_next = False
                    elif word.startswith(_KEPT_FLAGS):
                        kept.append(word)
                        take_next = word in ("-I", "-D", "-U", "-isystem", "-include")
                source = Path(os.path.realpath(directory / entry.get("file", "")))
                flags[str(source)] = _confined(kept, directory)
    return flags


def _confined(flags: list[str], directory: Path) -> list[str]:
    """Compile flags without those naming a folder or file outside the reading roots."""
    kept: list[str] = []
    pairs = zip(flags, [*flags[1:], ""])
    skip = False
    for flag, following in pairs:
        if skip:
            skip = False
            continue
        option = next((o for o in ("-isystem", "-include", "-I") if flag.startswith(o)), None)
        if option is None:
            kept.append(flag)
            continue
        joined = flag[len(option):]
        path, words = (joined, [flag]) if joined else (following, [flag, following])
        skip = not joined
        if sandbox.current().inside(directory / path):
            kept += words
    return kept


@lru_cache(maxsize=1)
def _nested_include_roots() -> list[str]:
    """Debian puts some ROS headers one level down (/usr/include/pluginlib/pluginlib/...), and so
    does ROS 2 since Humble (/opt/ros/humble/include/rclcpp/rclcpp/...); their build files add
    <include>/<name>, and so does archlog. So do libraries in a versioned folder
    (/usr/include/pcl-1.13/pcl/..., which find_package(PCL) adds)."""
    roots = [Path("/usr/include"), *sorted(Path(p) for p in glob.glob("/opt/ros/*/include"))]
    return sorted(str(d) for root in roots for d in root.glob("*")
                  if (d / d.name).is_dir() or (d / re.sub(r"-[0-9][0-9.]*$", "", d.name)).is_dir() and "-" in d.name)


_INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]', re.M)


def _load(index: ci.Index, source: Path, args: list[str], without_pch: list[str],
          unsaved: list[tuple[str, str]]) -> ci.TranslationUnit:
    try:
        return index.parse(str(source), args=args, unsaved_files=unsaved, options=_KEEP_GOING)
    except ci.TranslationUnitLoadError:
        return index.parse(str(source), args=without_pch, unsaved_files=unsaved, options=_KEEP_GOING)


_FOUND: dict[tuple[str, str], bool] = {}
"""Whether an include name is found, by (include environment's fingerprint, name): a worker
checks many cached files missing the same headers, each against hundreds of folders."""


def _still_valid(result: FileResult, env: CppEnvironment) -> bool:
    """A cached result holds while its headers are unchanged and its missing headers still are."""
    if any(file_stamp(path) != stamp for path, stamp in result.depends):
        return False
    folders = env.folders()
    for name in result.missing:
        if (env.fingerprint, name) not in _FOUND:
            _FOUND[(env.fingerprint, name)] = env.find(name, folders) is not None
    return not any(_FOUND[(env.fingerprint, name)] for name in result.missing)


def _reached_code(sources: list[Path], linked: Collection[Path], results: dict[Path, FileResult]) -> set[str] | None:
    """The functions the executable's own files reach (None: every function counts)."""
    graphs = {s: r.graph for s, r in results.items() if r.graph is not None}
    own = [graphs.get(s) for s in sources if s not in linked]
    if not linked or len(graphs) < len(results) or None in own:
        return None
    return reached(graphs.values(), {f for graph in own if graph is not None for f in graph.own})


def _merge(summary: NodeSummary, result: FileResult, diagnostics: DiagnosticSink, running: set[str] | None) -> None:
    """Add a file's result; with `running`, only its ports made in those functions (or outside any)."""
    graph = result.graph
    ports = [p for p in result.ports if running is None or graph is None
             or graph.ports.get((p.file, p.line, p.column), "") in running | {""}]
    known = set(summary.ports)
    summary.ports += [p for p in ports if p not in known]  # a header's code is read with each file
    summary.loads += [n for n in result.loads if n not in summary.loads]
    summary.plugin_loads += [at for at in result.plugin_loads if at not in summary.plugin_loads]
    if result.default_name is not None and summary.default_name is not None and \
            result.default_name != summary.default_name:
        summary.params_dynamic = summary.params_dynamic or f"{result.name_file}:{result.name_line}: the executable " \
            f"creates several nodes ({summary.default_name}, {result.default_name}), read as one: which parameters " \
            "each declares is not known"
    if result.default_name is not None and summary.default_name is None:
        summary.default_name, summary.anonymous = result.default_name, result.anonymous
        summary.name_file, summary.name_line = result.name_file, result.name_line
        summary.namespace = result.namespace
    summary.infrastructure = tuple(dict.fromkeys([*summary.infrastructure, *result.infrastructure]))
    summary.without = tuple(dict.fromkeys([*summary.without, *result.without]))
    summary.incomplete = summary.incomplete or result.incomplete
    summary.params_dynamic = summary.params_dynamic or result.params_dynamic
    diagnostics.extend(result.diagnostics)


def _tree_stamp(folders: list[Path]) -> list[str]:
    """(path, file_stamp) of every header under the workspace's include folders."""
    return [f"{path}:{file_stamp(path)}" for folder in folders for path in files_under(folder)
            if path.suffix in _HEADER_SUFFIXES and path.is_file()]


def _ros_pch(system: list[str], rdir: str | None) -> Path | None:
    """A precompiled ros/ros.h for this machine's headers, built once and kept in the cache; with
    boost::bind's placeholders global, as roscpp's headers gave them before Boost 1.73 (ROS 1 code
    writes boost::bind(&C::cb, this, _1) without including boost/bind.hpp)."""
    header = next((Path(d) / "ros" / "ros.h" for d in system if (Path(d) / "ros" / "ros.h").is_file()), None)
    if header is None or rdir is None:
        return None
    prelude = "#define BOOST_BIND_GLOBAL_PLACEHOLDERS\n#include <boost/bind.hpp>\n#include <ros/ros.h>\n"
    return _precompiled("ros", prelude, [f"-I{d}" for d in system], rdir, _tree_stamp([header.parent]))


@lru_cache(maxsize=1)
def _rclcpp_pch() -> Path | None:
    """The rclcpp stand-in precompiled (with the interfaces it declares), built once per machine."""
    rdir = resource_dir()
    deps = stand_in_dir(library_interfaces("rclcpp"), set(), Interfaces.index([]), lambda _name: False)
    if rdir is None or deps is None:
        return None
    return _precompiled("rclcpp-stand-in", '#include "archlog_ros2/rclcpp.hpp"\n', [f"-I{deps}", f"-I{API_DIR}"],
                        rdir, [_stand_in_stamp()])


def _precompiled(name: str, prelude_text: str, includes: list[str], rdir: str, stamps: list[str]) -> Path | None:
    """A PCH of a prelude, kept in the cache under a name keyed by everything it depends on."""
    args = ["-x", "c++-header", "-std=c++17", "-Wno-everything", "-resource-dir", rdir, *includes]
    stamp = key(ci.conf.lib.clang_getClangVersion.__name__, json.dumps(args), prelude_text, *stamps)
    target = cache_dir() / f"{name}-{stamp[:20]}.pch"
    if target.is_file():
        return target
    prelude = target.with_suffix(".hpp")  # clang reads the PCH's source again when loading it
    prelude.write_text(prelude_text)
    try:
        tu = ci.Index.create().parse(str(prelude), args=args, options=_KEEP_GOING | ci.TranslationUnit.PARSE_INCOMPLETE)
        if any(d.severity >= ci.Diagnostic.Error for d in tu.diagnostics):
            return None
        with tempfile.NamedTemporaryFile(dir=target.parent, suffix=".partial", delete=False) as partial:
            tu.save(partial.name)
        Path(partial.name).replace(target)
    except (ci.TranslationUnitLoadError, ci.TranslationUnitSaveError, OSError):
        return None
    return target
