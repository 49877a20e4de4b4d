"""roscpp nodes: parse C++ with libclang and hand each file to the walker (cpp_walk.py).

No compile database is needed: include paths come from the workspace (include/ folders and
include_directories()), headers generated for the workspace's own messages, /opt/ros/*/include
and /usr/include. ros/ros.h is precompiled once per machine (a PCH in the cache folder), and
each file's result is stored in an on-disk cache keyed by its content and every flag.
"""

from __future__ import annotations

import glob
import json
import re
import shlex
import shutil
import subprocess
import tempfile
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path

import clang.cindex as ci

from archlog.diagnostics import Diagnostic, DiagnosticSink
from archlog.extract.cache import ResultCache, cache_dir, key
from archlog.extract.cpp_walk import FileResult, walk
from archlog.extract.stub_headers import stub_dir
from archlog.extract.summary import NodeSummary

_KEEP_GOING = 0x200
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

    def __post_init__(self) -> None:
        system = sorted(glob.glob("/opt/ros/*/include")) + ["/usr/include"] + _nested_include_roots()
        includes = [str(p) for p in self.workspace_includes if p.is_dir()]
        includes += [str(self.generated)] if self.generated else []
        self.args = ["-x", "c++", "-std=c++17", "-Wno-everything", *(f"-I{d}" for d in includes + system)]
        rdir = resource_dir()
        if rdir:
            self.args += ["-resource-dir", rdir]
        self.pch = _ros_pch(system, rdir)
        self.per_file = _compile_commands(self.roots)
        self.fingerprint = key(json.dumps(self.parse_args()), *_tree_stamp(self.workspace_includes))

    def parse_args(self, source: Path | None = None) -> list[str]:
        pch = ["-include-pch", str(self.pch), "-Xclang", "-fno-validate-pch"] if self.pch else []
        return self.args + self.file_args(source) + pch

    def file_args(self, source: Path | None) -> list[str]:
        """Flags a compile database gives for this file (include paths, defines, standard)."""
        return self.per_file.get(str(source.resolve()), []) if source is not None else []


def extract_cpp(sources: list[Path], package: str, executable: str, env: CppEnvironment,
                shown: dict[Path, str], diagnostics: DiagnosticSink, cls: str | None = None) -> NodeSummary:
    """The summary of one executable (or of one nodelet class): every source file read, from the
    cache when unchanged."""
    summary = NodeSummary(package, executable, "cpp")
    cache = ResultCache("cpp")
    index: ci.Index | None = None
    for source in sources:
        name = shown.get(source, str(source))
        if not source.is_file():
            diagnostics.add(name, 1, "cpp-missing", "source file listed in CMakeLists.txt does not exist", "error")
            summary.incomplete = summary.incomplete or f"{name}: missing"
            continue
        cache_key = key(env.fingerprint, name, cls or "", " ".join(env.file_args(source)), source.read_bytes())
        result = cache.get(cache_key)
        if not isinstance(result, FileResult) or not _still_valid(result, env):
            index = index or ci.Index.create()
            result = _parse(index, source, name, env, cls)
            cache.put(cache_key, result)
        _merge(summary, result, diagnostics)
    return summary


def _parse(index: ci.Index, source: Path, shown: str, env: CppEnvironment, cls: str | None) -> FileResult:
    try:
        stubs = stub_dir(_unresolved_includes(source, env))
        extra = [f"-I{stubs}"] if stubs else []
        own = env.file_args(source)
        tu = _load(index, source, env.parse_args(source) + extra, env.args + own + extra)
        missing = [m.group(1) for d in tu.diagnostics if (m := _NOT_FOUND.search(d.spelling))]
        more = stub_dir(missing) if missing else None
        if more is not None and not extra:  # found only while parsing (included by a header): again
            tu = _load(index, source, env.parse_args(source) + [f"-I{more}"], env.args + own + [f"-I{more}"])
    except ci.TranslationUnitLoadError as exc:
        result = FileResult()
        result.diagnostics.append(Diagnostic(shown, 1, "cpp-parse", f"libclang could not parse this file: {exc}",
                                             "error"))
        result.incomplete = f"{shown}: could not be parsed"
        return result
    errors = [d for d in tu.diagnostics if d.severity >= ci.Diagnostic.Error and d.location.file
              and Path(d.location.file.name) == source]
    result = walk(tu, source, shown, incomplete_ast=bool(errors), cls=cls)
    result.depends = [(inc.include.name, _mtime(inc.include.name)) for inc in tu.get_includes()]
    result.missing = [m.group(1) for d in tu.diagnostics if (m := _NOT_FOUND.search(d.spelling))]
    if errors:
        first = errors[0]
        result.diagnostics.append(Diagnostic(shown, first.location.line, "cpp-compile",
                                             f"C++ does not compile here ({first.spelling}); calls were also read "
                                             "from the tokens", "warning"))
        if result.fallback_lines:
            result.incomplete = f"{shown}:{first.location.line}: does not compile"
    return result


_KEPT_FLAGS = ("-I", "-D", "-U", "-isystem", "-std=", "-include")


def _compile_commands(roots: list[Path]) -> dict[str, list[str]]:
    """Per-file flags from build/compile_commands.json (catkin/colcon with CMAKE_EXPORT_COMPILE_COMMANDS)."""
    flags: dict[str, list[str]] = {}
    for root in roots:
        for database in (root / "build" / "compile_commands.json", root / "compile_commands.json"):
            try:
                entries = json.loads(database.read_text())
            except (OSError, ValueError):
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
                source = (directory / entry.get("file", "")).resolve()
                flags[str(source)] = kept
    return flags


@lru_cache(maxsize=1)
def _nested_include_roots() -> list[str]:
    """Debian puts some ROS headers one level down (/usr/include/pluginlib/pluginlib/...); their
    pkg-config files add /usr/include/<name>, and so does archlog."""
    return sorted(str(d) for d in Path("/usr/include").glob("*") if (d / d.name).is_dir())


_INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]', re.M)


def _unresolved_includes(source: Path, env: CppEnvironment) -> list[str]:
    """The file's own #includes that no include folder (nor the file's folder) has."""
    folders = [source.parent] + [Path(a[2:]) for a in env.args if a.startswith("-I")]
    names = _INCLUDE.findall(source.read_text(errors="replace"))
    return [n for n in names if not any((folder / n).is_file() for folder in folders)]


def _load(index: ci.Index, source: Path, args: list[str], without_pch: list[str]) -> ci.TranslationUnit:
    try:
        return index.parse(str(source), args=args, options=_KEEP_GOING)
    except ci.TranslationUnitLoadError:
        return index.parse(str(source), args=without_pch, options=_KEEP_GOING)


def _mtime(path: str) -> int:
    try:
        return Path(path).stat().st_mtime_ns
    except OSError:
        return -1


def _still_valid(result: FileResult, env: CppEnvironment) -> bool:
    """A cached result holds while its headers are unchanged and its missing headers still are."""
    if any(_mtime(path) != mtime for path, mtime in result.depends):
        return False
    folders = [a[2:] for a in env.args if a.startswith("-I")]
    return not any((Path(folder) / name).is_file() for name in result.missing for folder in folders)


def _merge(summary: NodeSummary, result: FileResult, diagnostics: DiagnosticSink) -> None:
    summary.ports += result.ports
    if result.default_name is not None and summary.default_name is None:
        summary.default_name, summary.anonymous = result.default_name, result.anonymous
        summary.name_file, summary.name_line = result.name_file, result.name_line
    summary.incomplete = summary.incomplete or result.incomplete
    for diag in result.diagnostics:
        diagnostics.add(diag.file, diag.line, diag.code, diag.message, diag.severity, diag.column)


def _tree_stamp(folders: list[Path]) -> list[str]:
    """(path, size, mtime) of every header under the workspace's include folders."""
    stamps = []
    for folder in folders:
        if folder.is_dir():
            for path in sorted(folder.rglob("*")):
                if path.suffix in _HEADER_SUFFIXES and path.is_file():
                    stat = path.stat()
                    stamps.append(f"{path}:{stat.st_size}:{stat.st_mtime_ns}")
    return stamps


def _ros_pch(system: list[str], rdir: str | None) -> Path | None:
    """A precompiled ros/ros.h for this machine's headers, built once and kept in the cache."""
    header = next((Path(d) / "ros" / "ros.h" for d in system if (Path(d) / "ros" / "ros.h").is_file()), None)
    if header is None or rdir is None:
        return None
    args = ["-x", "c++-header", "-std=c++17", "-Wno-everything", "-resource-dir", rdir, *(f"-I{d}" for d in system)]
    stamp = key(ci.conf.lib.clang_getClangVersion.__name__, json.dumps(args),
                *_tree_stamp([header.parent]))
    target = cache_dir() / f"ros-{stamp[:20]}.pch"
    if target.is_file():
        return target
    prelude = target.with_suffix(".hpp")  # clang reads the PCH's source again when loading it
    prelude.write_text("#include <ros/ros.h>\n")
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
