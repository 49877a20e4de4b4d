"""Stand-in headers for message packages that are not installed, so that a file using them still
parses: `#include <control_msgs/FollowJointTrajectoryAction.h>` gets a minimal declaration of the
type (and of its service or action family). The type's name is taken from the code itself, so
the recovered types are exact; only the messages' fields are missing.
"""

from __future__ import annotations

import re
from pathlib import Path

from archlog.extract.cache import cache_dir

MESSAGE_INCLUDE = re.compile(r"^(\w+)/([A-Z]\w*)\.h$")

_STRUCT = """#ifndef ARCHLOG_STUB_{pkg}_{name}
#define ARCHLOG_STUB_{pkg}_{name}
namespace {pkg} {{
template <class ContainerAllocator> struct {name}_ {{
  typedef {name}_<ContainerAllocator> Type;
  typedef boost::shared_ptr<{name}_<ContainerAllocator> > Ptr;
  typedef boost::shared_ptr<{name}_<ContainerAllocator> const> ConstPtr;
{members}}};
typedef {name}_<std::allocator<void> > {name};
typedef boost::shared_ptr<{name}> {name}Ptr;
typedef boost::shared_ptr<{name} const> {name}ConstPtr;
}}
#endif
"""


def stub_dir(missing: list[str]) -> Path | None:
    """A folder with stand-ins for the missing message-like includes, or None if there are none."""
    wanted = [m for name in missing if (m := MESSAGE_INCLUDE.match(name))]
    if not wanted:
        return None
    folder = cache_dir() / "stubs"
    for match in wanted:
        target = folder / match.group(1) / f"{match.group(2)}.h"
        if not target.is_file():
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_text(_header(match.group(1), match.group(2)))
    return folder


def _struct(pkg: str, name: str, members: str = "") -> str:
    return _STRUCT.format(pkg=pkg, name=name, members=members)


def _header(pkg: str, name: str) -> str:
    parts = ["// archlog stand-in: the real header is not installed\n#pragma once\n#include <memory>\n"
             "#include <boost/shared_ptr.hpp>\n"]
    if name.endswith("Action"):
        base = name[: -len("Action")]
        for part in ("Goal", "Result", "Feedback"):
            parts.append(_struct(pkg, base + part))
            parts.append(_struct(pkg, f"{base}Action{part}",
                                 f"  typedef {base}{part}_<ContainerAllocator> _{part.lower()}_type;\n"
                                 f"  _{part.lower()}_type {part.lower()};\n"))
        parts.append(_struct(pkg, name, "".join(
            f"  typedef {base}Action{part}_<ContainerAllocator> _action_{part.lower()}_type;\n"
            for part in ("Goal", "Result", "Feedback"))))
    elif name.endswith(("Request", "Response")):
        parts.append(_struct(pkg, name))
    else:  # a message or a service: provide both shapes
        parts.append(_struct(pkg, name + "Request"))
        parts.append(_struct(pkg, name + "Response"))
        parts.append(_struct(pkg, name, f"  typedef {name}Request_<ContainerAllocator> Request;\n"
                                        f"  typedef {name}Response_<ContainerAllocator> Response;\n"
                                        "  Request request;\n  Response response;\n"))
    return "".join(parts)
