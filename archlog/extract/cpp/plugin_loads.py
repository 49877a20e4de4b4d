"""Where a C++ node creates pluginlib classes (pluginlib::ClassLoader's create*Instance calls).

Which classes it creates is chosen at run time, usually by its parameters, and their code is not
read with the node's: the ports they create are unknown. Each such call is kept as a hole of the
node (facts `plugin_hole`), so that a finding whose counterpart a plugin could provide says so.
A node model's `plugins:` slots, when they apply, say what the plugins create instead (system/link.py).
"""

from __future__ import annotations

import re

from archlog.extract.cpp.clang_ast import line_finder

CREATORS = ("createInstance", "createUniqueInstance", "createSharedInstance", "createUnmanagedInstance")
_CREATOR_CALL = re.compile(rf"(?:\.|->)\s*(?:{'|'.join(CREATORS)})\s*(?:<[^;()]*>)?\s*\(")
_STRING = re.compile(r'"(?:[^"\\\n]|\\.)*"')


def creates_plugin(owner: str, name: str) -> bool:
    """A call of pluginlib's class loader that creates an instance of a class named at run time."""
    return owner.startswith("pluginlib::ClassLoader") and name in CREATORS


def plugin_load_lines(text: str, spans: list[tuple[int, int]] | None) -> list[int]:
    """The lines of a (comment-blanked) C++ text that call a loader's create*Instance, for files whose
    AST lost the loader's type; within `spans` (the node's code) when given."""
    code = _STRING.sub(lambda m: " " * len(m.group()), text)
    line_of = line_finder(code)
    lines = [line_of(match.start()) for match in _CREATOR_CALL.finditer(code)]
    return [line for line in lines if spans is None or any(a <= line <= b for a, b in spans)]
