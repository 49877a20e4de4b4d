"""Golden files: what a test compares with, and how `pytest --update-goldens` rewrites it.

The golden files of the suite: the `findings` of every corpus `case.json`, the CodeQL-style
`*.expected` files of corpus/python, corpus/cpp_ros1 and corpus/cpp_ros2, the `findings.expected`
of every rule fixture (archlog/rules/builtin/tests, docs/examples/rules/tests; written by
`archlog test-rules --update`), and the generated docs (docs/facts.md, docs/rules.md, docs/diagnostics.md). Each is
rewritten only when it differs; review the diff before committing.
"""

from __future__ import annotations

import difflib
import json
import re
from pathlib import Path


def compare_text(path: Path, got: str, update: bool) -> str:
    """The unified diff from the golden file to `got` ('' when equal); with `update`, the file is
    rewritten first (only when it differs), so the diff is ''."""
    expected = path.read_text(encoding="utf-8") if path.is_file() else ""
    if update and got != expected:
        path.write_text(got, encoding="utf-8")
        expected = got
    return "".join(difflib.unified_diff(expected.splitlines(True), got.splitlines(True), f"{path} (golden)", "got"))


def rewrite_case_findings(case_file: Path, findings: list[dict]) -> None:
    """Replace the `findings` list of a case.json, keeping the rest of the file as written."""
    text = case_file.read_text(encoding="utf-8")
    key = re.search(r'^([ \t]*)"findings"\s*:\s*', text, re.MULTILINE)
    if key is None:
        data = json.loads(text)
        data["findings"] = findings
        case_file.write_text(json.dumps(data, indent=2) + "\n", encoding="utf-8")
        return
    _old, end = json.JSONDecoder().raw_decode(text, key.end())
    old_text = text[key.end():end]
    indent = key.group(1)
    if not findings:
        new_text = "[]"
    elif "{\n" in old_text or old_text.strip() == "[]":
        body = json.dumps(findings, indent=2).replace("\n", "\n" + indent)
        new_text = body
    else:  # one finding per line, as the file had it
        new_text = "[\n" + ",\n".join(f"{indent}  {json.dumps(f)}" for f in findings) + f"\n{indent}]"
    case_file.write_text(text[:key.end()] + new_text + text[end:], encoding="utf-8")
