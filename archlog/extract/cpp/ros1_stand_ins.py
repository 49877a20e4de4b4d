"""Stand-in headers for ROS 1 code: what archlog puts in place of ROS 1 headers that are not
installed (no ROS on the machine, or one package missing), so that the file still parses and its
calls are read from the syntax tree, as with the real headers. Only missing includes get one.

The libraries (roscpp, nodelet and pluginlib's export macro, actionlib, message_filters,
image_transport, tf and tf2_ros, dynamic_reconfigure's server, diagnostic_updater,
interactive_markers' server) are declared once, by hand, in `stand_ins/archlog_ros1/*.h` with
their real qualified names and signatures; a missing `#include <ros/node_handle.h>` gets a
one-line header forwarding to them. A missing message, service or action header (`pkg/Name.h`)
is generated: the struct templates gencpp would generate (`pkg::Name_<Allocator>`, `pkg::Name`,
`::ConstPtr`...), with fields and constants when the definition is found (the workspace's .msg,
.srv and .action files, Debian's), and without fields otherwise.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable
from functools import cache
from pathlib import Path

from archlog.extract.cpp.stubs import API_DIR, Interfaces, members, stand_ins_folder

# first component of a (non-message) include -> the stand-in declaring that library
ROS1_API = {"ros": "roscpp", "nodelet": "nodelet", "nodelet_topic_tools": "nodelet", "pluginlib": "nodelet",
            "actionlib": "actionlib", "message_filters": "message_filters", "image_transport": "image_transport",
            "tf": "tf", "tf2": "tf", "tf2_ros": "tf", "dynamic_reconfigure": "tools", "diagnostic_updater": "tools",
            "interactive_markers": "tools"}
# ROS 1: `#include <control_msgs/FollowJointTrajectoryAction.h>`
MESSAGE_INCLUDE = re.compile(r"^(\w+)/([A-Z]\w*)\.h$")
_INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]', re.M)
# definitions whose ROS 1 shape differs from the ROS 2 one Interfaces holds
_ROS1_DEFINITIONS = {("std_msgs", "msg", "Header"): "uint32 seq\ntime stamp\nstring frame_id\n"}
_ACTION_PARTS = ("Goal", "Result", "Feedback")


def ros1_library(include: str) -> str | None:
    """The library stand-in declaring what an include provides, if it is a ROS 1 library header."""
    return None if MESSAGE_INCLUDE.match(include) else ROS1_API.get(include.split("/", 1)[0])


def ros1_stand_in_dir(missing: Iterable[str], interfaces: Interfaces, exists: Callable[[str], bool]) -> Path | None:
    """A folder with stand-ins for the missing ROS 1 includes (and the headers they include that
    are missing too), or None when none of them is a ROS 1 library or message header."""

    def header(include: str) -> tuple[str, Iterable[str]]:
        library = ros1_library(include)
        if library is not None:
            return f'// archlog stand-in\n#include "archlog_ros1/{library}.h"\n', library_includes(library)
        return _message_header(include, interfaces)

    return stand_ins_folder([n for n in missing if ros1_library(n) or MESSAGE_INCLUDE.match(n)], header, exists)


@cache
def library_includes(library: str) -> tuple[str, ...]:
    """The ROS headers a library stand-in includes (roscpp, other libraries, messages): the real
    ones where installed, else stand-ins too."""
    text = (API_DIR / "archlog_ros1" / f"{library}.h").read_text()
    return tuple(name for name in _INCLUDE.findall(text) if ros1_library(name) or MESSAGE_INCLUDE.match(name))


def _message_header(include: str, interfaces: Interfaces) -> tuple[str, list[str]]:
    """The header gencpp would generate for pkg/Name.h (with the rest of its service or action
    family), and the headers it includes."""
    match = MESSAGE_INCLUDE.match(include)
    assert match is not None  # only message includes are generated
    pkg, name = match.groups()
    for kind, base in _family(name):
        definition = _ROS1_DEFINITIONS.get((pkg, kind, base)) or _definition(interfaces, pkg, kind, base)
        if definition is not None:
            return _family_header(pkg, kind, base, definition)
    if name.endswith("Action"):
        return _family_header(pkg, "action", name[: -len("Action")], "")
    if name.endswith(("Request", "Response")):
        return _header(pkg, [_struct(pkg, name)]), ["ros/time.h"]
    both = f"  typedef {name}Request_<ContainerAllocator> Request;\n  typedef {name}Response_<ContainerAllocator> " \
        "Response;\n  Request request;\n  Response response;\n"  # a message or a service: both shapes
    return _header(pkg, [_struct(pkg, f"{name}Request"), _struct(pkg, f"{name}Response"), _struct(pkg, name, both)]), \
        ["ros/time.h"]


def _family(name: str) -> list[tuple[str, str]]:
    """(kind, definition name) the type of a header may belong to."""
    found = [("msg", name), ("srv", name)]
    found += [("srv", name[: -len(suffix)]) for suffix in ("Request", "Response") if name.endswith(suffix)]
    found += [("action", name[: -len(suffix)]) for suffix in ("ActionGoal", "ActionResult", "ActionFeedback",
                                                                "Action", *_ACTION_PARTS) if name.endswith(suffix)]
    return found


def _definition(interfaces: Interfaces, pkg: str, kind: str, name: str) -> str | None:
    found = interfaces.lookup(pkg, kind, name.lower()) if name else None
    return found[1] if found is not None and found[0] == name else None


def _family_header(pkg: str, kind: str, base: str, definition: str) -> tuple[str, list[str]]:
    sections = re.split(r"^---\s*$", definition, flags=re.M)
    fields = [members(section, pkg, _nested, "boost::array", field_types=True) for section in sections]
    includes = [include for _text, nested in fields for include in nested]
    texts = [text for text, _nested in fields] + [""] * 3
    if kind == "msg":
        structs = [_struct(pkg, base, texts[0])]
    elif kind == "srv":
        structs = [_struct(pkg, f"{base}Request", texts[0]), _struct(pkg, f"{base}Response", texts[1]),
                   _service(pkg, base)]
    else:
        structs = [_struct(pkg, f"{base}{part}", texts[index]) for index, part in enumerate(_ACTION_PARTS)]
        structs += [_struct(pkg, f"{base}Action{part}",
                            f"  typedef {base}{part}_<ContainerAllocator> _{part.lower()}_type;\n"
                            f"  _{part.lower()}_type {part.lower()};\n") for part in _ACTION_PARTS]
        structs.append(_struct(pkg, f"{base}Action", "".join(
            f"  typedef {base}Action{part}_<ContainerAllocator> _action_{part.lower()}_type;\n"
            f"  _action_{part.lower()}_type action_{part.lower()};\n" for part in _ACTION_PARTS)))
    return _header(pkg, structs, includes), ["ros/time.h", *dict.fromkeys(includes)]


def _nested(base: str, pkg: str) -> tuple[str, str | None]:
    """The C++ type of a field of a non-primitive type, and its header."""
    if base in ("time", "duration"):
        return f"ros::{base.capitalize()}", None
    owner, _, type_name = base.rpartition("/")
    owner = "std_msgs" if base == "Header" else owner or pkg
    return f"{owner}::{type_name}_<ContainerAllocator>", f"{owner}/{type_name}.h"


def _header(pkg: str, structs: list[str], includes: Iterable[str] = ()) -> str:
    return (f"// archlog stand-in: a {pkg} header that is not installed\n#pragma once\n#include <cstdint>\n"
            "#include <memory>\n#include <string>\n#include <vector>\n#include <boost/array.hpp>\n"
            "#include <boost/shared_ptr.hpp>\n#include <ros/time.h>\n"
            + "".join(f"#include <{n}>\n" for n in dict.fromkeys(includes)) + "".join(structs))


def _struct(pkg: str, name: str, fields: str = "") -> str:
    guard = f"ARCHLOG_STAND_IN_{pkg}_{name}".upper()
    return (f"#ifndef {guard}\n#define {guard}\nnamespace {pkg}\n{{\n"
            f"template<class ContainerAllocator> struct {name}_\n{{\n"
            f"  typedef {name}_<ContainerAllocator> Type;\n"
            f"  typedef boost::shared_ptr<{name}_<ContainerAllocator> > Ptr;\n"
            f"  typedef boost::shared_ptr<{name}_<ContainerAllocator> const> ConstPtr;\n"
            f"  {name}_();\n  explicit {name}_(const ContainerAllocator & allocator);\n{fields}}};\n"
            f"typedef {name}_<std::allocator<void> > {name};\n"
            f"typedef boost::shared_ptr<{name}> {name}Ptr;\n"
            f"typedef boost::shared_ptr<{name} const> {name}ConstPtr;\n}}  // namespace {pkg}\n#endif\n")


def _service(pkg: str, name: str) -> str:
    guard = f"ARCHLOG_STAND_IN_{pkg}_{name}_SERVICE".upper()
    return (f"#ifndef {guard}\n#define {guard}\nnamespace {pkg}\n{{\nstruct {name}\n{{\n"
            f"  typedef {name}Request Request;\n  typedef {name}Response Response;\n"
            f"  Request request;\n  Response response;\n}};\n}}  // namespace {pkg}\n#endif\n")
