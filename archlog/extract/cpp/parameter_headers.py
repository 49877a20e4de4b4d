"""Stand-ins for the headers generate_parameter_library builds, so that a node's code using them parses.

The build writes `include/<package>/<library>.hpp` from the library's YAML definition; it is never
in the source tree. This writes, under the cache, a header of that name with the definition's
namespace, a `Params` struct holding every parameter (nested structs for dotted names) and a
`ParamListener` whose constructor takes anything. The parameters themselves come from the
definition (extract/parameter_library.py), not from this header.
"""

from __future__ import annotations

import hashlib
import re
from pathlib import Path

from archlog import sandbox
from archlog.extract.cpp.cache import cache_dir
from archlog.extract.parameter_library import DefinitionError, load
from archlog.extract.workspace.index import Workspace

CPP_TYPES = {"bool": "bool", "int": "int64_t", "double": "double", "string": "std::string"}
_IDENTIFIER = re.compile(r"[A-Za-z_]\w*")


def parameter_headers(workspace: Workspace) -> Path | None:
    """The include folder of the stand-in headers of every parameter library of the workspace, or
    None when there is none (a definition that cannot be read gets no header: the node's code is
    then read as not compiling, and extract/parameter_library.py reports the file)."""
    headers: dict[str, str] = {}
    for package in workspace.packages.values():
        for library, path in package.parameter_libraries.items():
            try:
                namespace, found, _lines = load(path)
            except (sandbox.Refused, DefinitionError):
                continue
            if _IDENTIFIER.fullmatch(library) and all(_IDENTIFIER.fullmatch(p) for p in namespace.split("::")):
                headers[f"{package.name}/{library}.hpp"] = _header(namespace, found)
    if not headers:
        return None
    digest = hashlib.sha256("\0".join(f"{k}\0{v}" for k, v in sorted(headers.items())).encode()).hexdigest()[:24]
    out = cache_dir() / "param_headers" / digest
    for name, text in headers.items():
        target = out / name
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_text(text, encoding="utf-8")
    return out


def _header(namespace: str, found: dict[str, dict]) -> str:
    tree: dict = {}
    for name, entry in found.items():
        parts = name.split(".")
        if all(_IDENTIFIER.fullmatch(p) for p in parts):
            node = tree
            for part in parts[:-1]:
                node = node.setdefault(part, {})
                if not isinstance(node, dict):
                    break
            else:
                node[parts[-1]] = _cpp_type(str(entry.get("type", "")))
    return ("// archlog's stand-in for a header generate_parameter_library generates\n#pragma once\n"
            "#include <cstdint>\n#include <string>\n#include <vector>\n\n"
            f"namespace {namespace} {{\n\nstruct Params {{\n{_members(tree, '  ')}}};\n\n"
            "class ParamListener {\npublic:\n  template <typename... Args> explicit ParamListener(Args &&...) {}\n"
            "  Params get_params() const { return Params(); }\n  bool is_old(const Params &) const { return false; }\n"
            "  void refresh_dynamic_parameters() {}\n};\n\n"
            f"}}  // namespace {namespace}\n")


def _members(tree: dict, indent: str) -> str:
    lines = []
    for name, value in tree.items():
        if isinstance(value, dict):
            lines.append(f"{indent}struct {name.capitalize()}_ {{\n{_members(value, indent + '  ')}{indent}}} {name};\n")
        else:
            lines.append(f"{indent}{value} {name}{{}};\n")
    return "".join(lines)


def _cpp_type(declared: str) -> str:
    base = re.sub(r"_fixed_\d+$", "", declared)
    if base.endswith("_array"):
        return f"std::vector<{CPP_TYPES.get(base.removesuffix('_array'), 'double')}>"
    return CPP_TYPES.get(base, "double")
