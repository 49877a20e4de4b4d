"""`archlog check --fix`: the edits a rule's `fix` makes in the user's launch files.

A rule's `fix: {remap: [node, from, to], safe: BOOL}` names the node whose launch element gets a
remap of `from` onto `to` (resolved names: a remap matches names after resolution in ROS 1 and
ROS 2 alike). In launch XML (ROS 1, ROS 2) the element gets `<remap from=... to=.../>`; in a Python
launch file the `Node(...)` call gets `remappings=[(...)]` (or one more pair in its literal list).
A node declared elsewhere (YAML launch, a computed remappings list) gets no fix. Two fixes of
one element in one run: the first is applied, the second waits for the next run.

A rule's `fix: {rename: [at, from, to], safe: BOOL}` renames a parameter where the configuration
sets it (the line of the column `at`: a `<param>`, a key of a parameter file, a `parameters=`
dictionary, `-p name:=`): the last segment of `from` becomes that of `to` when both have the same
namespace and that segment is written exactly once on the line; anything else gets no fix.
"""

from __future__ import annotations

import ast
import difflib
import re
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from xml.sax.saxutils import quoteattr

from archlog.rules.engine import Finding
from archlog.values import Unknown


@dataclass(frozen=True)
class Edit:
    file: Path
    start: int  # character offsets into the file's text
    end: int
    text: str


@dataclass
class Fix:
    finding: Finding
    edit: Edit
    what: str  # "remap /a to /b on /node"

    @property
    def safe(self) -> bool:
        return self.finding.rule.fix_safe


def _xml_remap(text: str, line: int, source: str, target: str) -> tuple[int, int, str] | None:
    """The edit adding a remap to the `<node>` element whose start tag ends on or before `line`."""
    lines = text.split("\n")
    upto = sum(len(part) + 1 for part in lines[:line])
    starts = [m.start() for m in re.finditer(r"<node[\s/>]", text[:upto])]
    if not starts:
        return None
    start = starts[-1]
    quote, i = "", start
    while i < len(text):  # the end of the start tag, outside attribute values
        char = text[i]
        if quote:
            quote = "" if char == quote else quote
        elif char in "\"'":
            quote = char
        elif char == ">":
            break
        i += 1
    else:
        return None
    line_start = text.rfind("\n", 0, start) + 1
    indent = text[line_start:start] if not text[line_start:start].strip() else ""
    remap = f"{indent}  <remap from={quoteattr(source)} to={quoteattr(target)}/>"
    if text[i - 1] == "/":
        begin = len(text[:i - 1].rstrip())
        return begin, i + 1, f">\n{remap}\n{indent}</node>"
    return i + 1, i + 1, f"\n{remap}"


def _offset(text: str, line: int, column: int) -> int:
    """The character offset of an ast position (its column counts UTF-8 bytes)."""
    lines = text.split("\n")
    return sum(len(part) + 1 for part in lines[:line - 1]) + len(lines[line - 1].encode()[:column].decode())


def _python_remap(text: str, line: int, source: str, target: str) -> tuple[int, int, str] | None:
    """The edit adding a remapping to the `...Node(...)` call that starts on `line`."""
    try:
        tree = ast.parse(text)
    except SyntaxError:
        return None
    calls = [n for n in ast.walk(tree) if isinstance(n, ast.Call) and n.lineno == line
             and (n.func.id if isinstance(n.func, ast.Name) else getattr(n.func, "attr", "")).endswith("Node")]
    if len(calls) != 1:
        return None
    call, pair = calls[0], f"({source!r}, {target!r})".replace("'", '"')
    given = next((k.value for k in call.keywords if k.arg == "remappings"), None)
    if given is not None:
        if not isinstance(given, ast.List):
            return None
        at = _offset(text, given.lineno, given.col_offset) + 1
        return at, at, pair + (", " if given.elts else "")
    close = _offset(text, call.end_lineno or call.lineno, call.end_col_offset or 0) - 1
    before = text[:close].rstrip()
    lead = " " if before.endswith(",") else "" if before.endswith("(") else ", "
    return len(before), len(before), f"{lead}remappings=[{pair}]"


def _rename(text: str, line: int, source: str, target: str) -> tuple[int, int, str] | None:
    """The edit renaming the parameter `source` to `target` (relative names) on `line`."""
    old_ns, _, old = source.lstrip("~").rpartition("/")
    new_ns, _, new = target.lstrip("~").rpartition("/")
    lines = text.split("\n")
    if old_ns != new_ns or not 0 < line <= len(lines):
        return None
    found = list(re.finditer(rf"(?<![\w/]){re.escape(old)}(?![\w])", lines[line - 1]))
    if len(found) != 1:
        return None
    start = sum(len(part) + 1 for part in lines[:line - 1]) + found[0].start()
    return start, start + len(old), new


def plan(findings: list[Finding], store, absolute: Callable[[str], Path]) -> list[Fix]:
    """The fix of each finding whose rule has one and whose node (a remap) or parameter (a rename)
    is written in a file archlog can edit; `absolute` turns a fact's file into a path."""
    elements = {str(name): str(elem) for name, _pkg, _exe, elem in store.rows("node")}
    fixes, seen = [], set()
    for finding in findings:
        if finding.rule.fix is None or finding.suppression is not None:
            continue
        first, source, target = (finding.values.get(c) for c in finding.rule.fix)
        if any(isinstance(v, Unknown) or v is None or v == "none" for v in (first, source, target)) \
                or source == target:
            continue
        rename = finding.rule.fix_kind == "rename"
        where = store.location(str(first) if rename else elements.get(str(first), ""))
        if not where or (where[0], where[1], str(source)) in seen:
            continue
        path = absolute(where[0])
        try:
            text = path.read_text(encoding="utf-8")
        except OSError:
            continue
        make = _rename if rename else _python_remap if path.suffix == ".py" \
            else _xml_remap if path.suffix in (".launch", ".xml") else None
        edit = make(text, where[1], str(source), str(target)) if make else None
        if edit is not None:
            seen.add((where[0], where[1], str(source)))
            what = f"rename {source} to {target}" if rename else f"remap {source} to {target} on {first}"
            fixes.append(Fix(finding, Edit(path, *edit), what))
    return fixes


def chosen(fixes: list[Fix], unsafe: bool) -> list[Fix]:
    """The fixes to apply: safe ones, and the others with `unsafe`; of overlapping edits the first."""
    result: list[Fix] = []
    for fix in fixes:
        if (fix.safe or unsafe) and not any(f.edit.file == fix.edit.file and f.edit.start <= fix.edit.end
                                            and fix.edit.start <= f.edit.end for f in result):
            result.append(fix)
    return result


def edited(fixes: list[Fix]) -> dict[Path, tuple[str, str]]:
    """Each file the fixes touch: (text before, text after)."""
    result: dict[Path, tuple[str, str]] = {}
    for file in sorted({f.edit.file for f in fixes}):
        before = file.read_text(encoding="utf-8")
        after = before
        for edit in sorted((f.edit for f in fixes if f.edit.file == file), key=lambda e: e.start, reverse=True):
            after = after[:edit.start] + edit.text + after[edit.end:]
        result[file] = (before, after)
    return result


def unified(changes: dict[Path, tuple[str, str]], shown: Callable[[Path], str]) -> str:
    """The changes as one unified diff, with paths as `shown` names them."""
    return "".join("".join(difflib.unified_diff(before.splitlines(keepends=True), after.splitlines(keepends=True),
                                                f"a/{shown(file)}", f"b/{shown(file)}"))
                   for file, (before, after) in changes.items())
