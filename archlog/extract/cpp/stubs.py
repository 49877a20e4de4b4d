"""Stand-in headers: what archlog puts in place of headers that are not installed, so that a
file using them still parses. All of them are written to the cache, searched before every other
include folder; only missing includes get one.

ROS 2 code, two kinds: the client libraries (rclcpp, rclcpp_lifecycle, rclcpp_action,
rclcpp_components, tf2, tf2_ros, image_transport, message_filters, diagnostic_updater, bondcpp,
rmw, sensor_msgs' helpers) are declared once, by hand, in the shipped `stand_ins/archlog_ros2/*.hpp`
with their real qualified names and signatures; a missing `#include "rclcpp/node.hpp"` gets a
one-line header forwarding to them. Message, service and action headers
(`std_msgs/msg/string.hpp`) are generated: the struct templates rosidl would generate
(`std_msgs::msg::String_<Allocator>`, `String`, `::SharedPtr`...), with fields and constants when
the definition is found (the workspace's .msg/.srv/.action files, a few ROS 2 core interfaces
below, Debian's ROS 1 definitions of the common packages) and with the type's name as the code
spells it otherwise. ROS 1 headers of packages that exist in both ROS versions under the same
include names (tf2_ros, image_transport, message_filters, diagnostic_updater, bondcpp) do not
count as present for ROS 2 code. The headers of one translation unit go to a folder named after
their content.

ROS 1 code: ros1_stand_ins.py.
"""

from __future__ import annotations

import hashlib
import os
import re
import tempfile
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from pathlib import Path

from archlog import sandbox
from archlog.extract.cpp.cache import cache_dir

API_DIR = Path(__file__).with_name("stand_ins")
# first component of an include -> the stand-in declaring that library
API = {"rclcpp": "rclcpp", "rmw": "rclcpp", "rcl": "rclcpp", "rclcpp_lifecycle": "rclcpp_lifecycle",
       "rclcpp_action": "rclcpp_action", "rclcpp_components": "rclcpp_components", "tf2_ros": "tf2_ros",
       "image_transport": "image_transport", "message_filters": "message_filters",
       "diagnostic_updater": "diagnostic_updater", "bondcpp": "bondcpp", "tf2": "tf2", "tf2_geometry_msgs": "tf2"}
# C++ helpers of interface packages (whose other headers are interfaces)
HELPERS = {"sensor_msgs/point_cloud2_iterator.hpp": "sensor_msgs", "sensor_msgs/image_encodings.hpp": "sensor_msgs"}
# tf2 headers that ROS 1 has with the same content under a .h name
_TF2_SAME_AS_ROS1 = re.compile(r"^tf2/(LinearMath/\w+|exceptions)\.hpp$")
# ROS 1 packages whose headers have the same include names as in ROS 2
DUAL = {"tf2_ros", "image_transport", "message_filters", "diagnostic_updater", "bondcpp"}
INTERFACE_INCLUDE = re.compile(r"^(\w+)/(msg|srv|action)/(\w+)\.hpp$")
ROS2_MARKERS = re.compile(r'^\s*#\s*include\s*[<"](?:rclcpp\w*/|\w+/(?:msg|srv|action)/\w+\.hpp)', re.M)
_INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]', re.M)

# ROS 2 core interfaces the client libraries use, and the most common service and action types,
# which Debian's ROS 1 does not ship (or ships in their ROS 1 shape: std_msgs/Header has no seq
# in ROS 2)
EMBEDDED = {
    "builtin_interfaces/msg/Time": "int32 sec\nuint32 nanosec\n",
    "builtin_interfaces/msg/Duration": "int32 sec\nuint32 nanosec\n",
    "std_msgs/msg/Header": "builtin_interfaces/Time stamp\nstring frame_id\n",
    "rcl_interfaces/msg/FloatingPointRange": "float64 from_value\nfloat64 to_value\nfloat64 step\n",
    "rcl_interfaces/msg/IntegerRange": "int64 from_value\nint64 to_value\nuint64 step\n",
    "rcl_interfaces/msg/ParameterDescriptor": (
        "string name\nuint8 type\nstring description\nstring additional_constraints\nbool read_only false\n"
        "bool dynamic_typing false\nFloatingPointRange[<=1] floating_point_range\nIntegerRange[<=1] integer_range\n"),
    "rcl_interfaces/msg/SetParametersResult": "bool successful\nstring reason\n",
    "rcl_interfaces/msg/ListParametersResult": "string[] names\nstring[] prefixes\n",
    "rcl_interfaces/msg/ParameterType": "".join(
        f"uint8 PARAMETER_{name}={value}\n" for value, name in enumerate(
            ("NOT_SET", "BOOL", "INTEGER", "DOUBLE", "STRING", "BYTE_ARRAY", "BOOL_ARRAY", "INTEGER_ARRAY",
             "DOUBLE_ARRAY", "STRING_ARRAY"))),
    "lifecycle_msgs/msg/State": (
        "uint8 PRIMARY_STATE_UNKNOWN=0\nuint8 PRIMARY_STATE_UNCONFIGURED=1\nuint8 PRIMARY_STATE_INACTIVE=2\n"
        "uint8 PRIMARY_STATE_ACTIVE=3\nuint8 PRIMARY_STATE_FINALIZED=4\nuint8 TRANSITION_STATE_CONFIGURING=10\n"
        "uint8 TRANSITION_STATE_CLEANINGUP=11\nuint8 TRANSITION_STATE_SHUTTINGDOWN=12\n"
        "uint8 TRANSITION_STATE_ACTIVATING=13\nuint8 TRANSITION_STATE_DEACTIVATING=14\n"
        "uint8 TRANSITION_STATE_ERRORPROCESSING=15\nuint8 id\nstring label\n"),
    "lifecycle_msgs/msg/Transition": (
        "uint8 TRANSITION_CREATE=0\nuint8 TRANSITION_CONFIGURE=1\nuint8 TRANSITION_CLEANUP=2\n"
        "uint8 TRANSITION_ACTIVATE=3\nuint8 TRANSITION_DEACTIVATE=4\nuint8 TRANSITION_UNCONFIGURED_SHUTDOWN=5\n"
        "uint8 TRANSITION_INACTIVE_SHUTDOWN=6\nuint8 TRANSITION_ACTIVE_SHUTDOWN=7\nuint8 TRANSITION_DESTROY=8\n"
        "uint8 TRANSITION_CALLBACK_SUCCESS=97\nuint8 TRANSITION_CALLBACK_FAILURE=98\n"
        "uint8 TRANSITION_CALLBACK_ERROR=99\nuint8 id\nstring label\n"),
    "lifecycle_msgs/msg/TransitionEvent": ("uint64 timestamp\nTransition transition\nState start_state\n"
                                           "State goal_state\n"),
    "lifecycle_msgs/srv/ChangeState": "Transition transition\n---\nbool success\n",
    "lifecycle_msgs/srv/GetState": "---\nState current_state\n",
    "unique_identifier_msgs/msg/UUID": "uint8[16] uuid\n",
    "action_msgs/msg/GoalInfo": "unique_identifier_msgs/UUID goal_id\nbuiltin_interfaces/Time stamp\n",
    "action_msgs/msg/GoalStatus": (
        "int8 STATUS_UNKNOWN=0\nint8 STATUS_ACCEPTED=1\nint8 STATUS_EXECUTING=2\nint8 STATUS_CANCELING=3\n"
        "int8 STATUS_SUCCEEDED=4\nint8 STATUS_CANCELED=5\nint8 STATUS_ABORTED=6\nGoalInfo goal_info\nint8 status\n"),
    "action_msgs/msg/GoalStatusArray": "GoalStatus[] status_list\n",
    "action_msgs/srv/CancelGoal": (
        "GoalInfo goal_info\n---\nint8 ERROR_NONE=0\nint8 ERROR_REJECTED=1\nint8 ERROR_UNKNOWN_GOAL_ID=2\n"
        "int8 ERROR_GOAL_TERMINATED=3\nint8 return_code\nGoalInfo[] goals_canceling\n"),
    "tf2_msgs/msg/TFMessage": "geometry_msgs/TransformStamped[] transforms\n",
    "diagnostic_msgs/srv/SelfTest": "---\nstring id\nbyte passed\nDiagnosticStatus[] status\n",
    "std_srvs/srv/Empty": "---\n",
    "std_srvs/srv/Trigger": "---\nbool success\nstring message\n",
    "std_srvs/srv/SetBool": "bool data\n---\nbool success\nstring message\n",
    "example_interfaces/srv/AddTwoInts": "int64 a\nint64 b\n---\nint64 sum\n",
    "example_interfaces/action/Fibonacci": "int32 order\n---\nint32[] sequence\n---\nint32[] sequence\n",
    "diagnostic_msgs/msg/KeyValue": "string key\nstring value\n",
    "diagnostic_msgs/msg/DiagnosticStatus": (
        "byte OK=0\nbyte WARN=1\nbyte ERROR=2\nbyte STALE=3\nbyte level\nstring name\nstring message\n"
        "string hardware_id\nKeyValue[] values\n"),
    "diagnostic_msgs/msg/DiagnosticArray": "std_msgs/Header header\nDiagnosticStatus[] status\n",
}
_PRIMITIVES = {
    "bool": "bool", "byte": "uint8_t", "char": "uint8_t", "int8": "int8_t", "uint8": "uint8_t", "int16": "int16_t",
    "uint16": "uint16_t", "int32": "int32_t", "uint32": "uint32_t", "int64": "int64_t", "uint64": "uint64_t",
    "float32": "float", "float64": "double", "string": "std::string", "wstring": "std::u16string",
}
_ROS1_BUILTINS = {"time": ("builtin_interfaces", "Time"), "duration": ("builtin_interfaces", "Duration"),
                  "Header": ("std_msgs", "Header")}
_FIELD = re.compile(r"^(?P<type>[\w/]+)(?:<=\d+)?(?P<array>\[(?P<size><=)?(?P<n>\d*)\])?\s+(?P<name>\w+)"
                    r"\s*(?:=\s*(?P<constant>.*))?")
_PART = {"msg": ("",), "srv": ("_Request", "_Response"), "action": ("_Goal", "_Result", "_Feedback")}


def snake(name: str) -> str:
    """rosidl's header name for a type: LaserScan -> laser_scan, TFMessage -> tf_message."""
    name = re.sub(r"(.)([A-Z][a-z]+)", r"\1_\2", name)
    return re.sub(r"([a-z0-9])([A-Z])", r"\1_\2", name).lower()


def is_ros2(text: str) -> bool:
    """A file written for ROS 2: it includes rclcpp or a ROS 2 interface header."""
    return ROS2_MARKERS.search(text) is not None


@dataclass
class Interfaces:
    """Interface definitions by (package, kind): {squashed name: (Name, definition file or text)}."""

    found: dict[tuple[str, str], dict[str, tuple[str, Path | str]]] = field(default_factory=dict)

    @classmethod
    def index(cls, package_dirs: Iterable[Path]) -> Interfaces:
        """Debian's ROS 1 definitions, then the ROS 2 core ones above, then the workspace's."""
        index = cls()
        for share in sorted(Path("/usr/share").glob("*/msg")) + sorted(Path("/usr/share").glob("*/srv")):
            index._add_folder(share.parent.name, share)
        for qualified, text in EMBEDDED.items():
            pkg, kind, name = qualified.split("/")
            index.found.setdefault((pkg, kind), {})[name.lower()] = (name, text)
        for folder in package_dirs:
            for kind in ("msg", "srv", "action"):
                index._add_folder(folder.name, folder / kind)
        return index

    def _add_folder(self, pkg: str, folder: Path) -> None:
        if folder.is_dir():
            for path in sorted(folder.glob(f"*.{folder.name}")):
                self.found.setdefault((pkg, folder.name), {})[path.stem.lower()] = (path.stem, path)

    def stamp(self) -> list[str]:
        """(path, size, mtime) of every definition file, for cache keys."""
        return [f"{p}:{p.stat().st_size}:{p.stat().st_mtime_ns}" for kinds in self.found.values()
                for _n, p in kinds.values() if isinstance(p, Path) and p.is_file()]

    def lookup(self, pkg: str, kind: str, header: str) -> tuple[str, str] | None:
        entry = self.found.get((pkg, kind), {}).get(header.replace("_", ""))
        if entry is None:
            return None
        name, source = entry
        try:
            return name, sandbox.read_text(source, "message") if isinstance(source, Path) else source
        except sandbox.Refused:
            return None


def stand_in_dir(missing: Iterable[str], spellings: set[str], interfaces: Interfaces,
                 exists: Callable[[str], bool]) -> Path | None:
    """A folder with stand-ins for the missing ROS 2 includes (and the interfaces they need), or
    None when none of them is a ROS 2 library or interface header."""

    def header(include: str) -> tuple[str, Iterable[str]]:
        library = library_for(include)
        if library is not None:
            same = _TF2_SAME_AS_ROS1.match(include)
            return (f"// archlog stand-in\n#include <tf2/{same.group(1)}.h>\n" if same else
                    f'// archlog stand-in\n#include "archlog_ros2/{library}.hpp"\n'), library_interfaces(library)
        match = INTERFACE_INCLUDE.match(include)
        assert match is not None  # only library and interface includes are asked for
        pkg, kind, name = match.groups()
        return _interface_header(pkg, kind, name, spellings, interfaces)

    return stand_ins_folder([n for n in missing if library_for(n) or INTERFACE_INCLUDE.match(n)], header, exists)


def stand_ins_folder(missing: list[str], header: Callable[[str], tuple[str, Iterable[str]]],
                     exists: Callable[[str], bool]) -> Path | None:
    """A folder with a stand-in for each missing include (`header(include)`: its text and the
    includes it needs) and for each include they need that does not exist; None when none is missing."""
    files: dict[str, str] = {}
    pending = list(missing)
    while pending:
        include = pending.pop()
        if include in files:
            continue
        files[include], needed = header(include)
        pending += [n for n in needed if n not in files and not exists(n)]
    return headers_folder(files) if files else None


def headers_folder(files: dict[str, str]) -> Path:
    """A folder in the cache holding these headers (by include name), named after their content."""
    digest = hashlib.sha256("\0".join(f"{k}\0{v}" for k, v in sorted(files.items())).encode()).hexdigest()[:24]
    folder = cache_dir() / "stand_ins" / digest
    if not (folder / ".done").is_file():
        _write_folder(folder, files)
    return folder


def library_for(include: str) -> str | None:
    """The library stand-in declaring what an include provides, if it is a ROS 2 library header."""
    return HELPERS.get(include) or API.get(include.split("/", 1)[0])


def spelled_types(texts: Iterable[str]) -> set[str]:
    """`pkg::msg::Name` as written in the sources (the exact names of the types they use)."""
    return {m.group(0) for text in texts for m in re.finditer(r"\b\w+::(?:msg|srv|action)::[A-Z]\w*", text)}


def library_interfaces(library: str, seen: set[str] | None = None) -> list[str]:
    """The interface headers a library stand-in includes, directly or through another stand-in."""
    seen = set() if seen is None else seen
    seen.add(library)
    found = []
    for include in _INCLUDE.findall((API_DIR / "archlog_ros2" / f"{library}.hpp").read_text()):
        if INTERFACE_INCLUDE.match(include):
            found.append(include)
        elif include.startswith("archlog_ros2/") and (other := Path(include).stem) not in seen:
            found += library_interfaces(other, seen)
    return found


def _interface_header(pkg: str, kind: str, header: str, spellings: set[str],
                      interfaces: Interfaces) -> tuple[str, list[str]]:
    """The header rosidl would generate for pkg/kind/header.hpp, and the headers it includes."""
    found = interfaces.lookup(pkg, kind, header)
    if found is not None:
        name, definition = found
    else:
        spelled = [s.rsplit("::", 1)[1] for s in spellings if s.startswith(f"{pkg}::{kind}::")]
        name = next((s for s in sorted(spelled) if s.lower() == header.replace("_", "")),
                    "".join(part.capitalize() for part in header.split("_")))
        definition = ""
    sections = re.split(r"^---\s*$", definition, flags=re.M) if definition else []
    includes: list[str] = []
    body = []
    for index, suffix in enumerate(_PART[kind]):
        fields, nested = members(sections[index] if index < len(sections) else "", pkg)
        includes += nested
        body.append(_struct(f"{name}{suffix}", fields))
    if kind != "msg":
        aliases = "".join(f"  using {suffix[1:]} = {name}{suffix};\n" for suffix in _PART[kind])
        body.append(f"struct {name}\n{{\n{aliases}}};\n")
    guard = f"ARCHLOG_STAND_IN_{pkg}_{kind}_{header}".upper()
    text = (f"// archlog stand-in: {pkg}/{kind}/{name} ({'fields from its definition' if definition else 'no fields'})"
            f"\n#ifndef {guard}\n#define {guard}\n#include <array>\n#include <cstdint>\n#include <memory>\n"
            "#include <string>\n#include <vector>\n"
            + "".join(f'#include "{n}"\n' for n in dict.fromkeys(includes))
            + f"namespace {pkg}\n{{\nnamespace {kind}\n{{\n" + "".join(body) + f"}}  // namespace {kind}\n"
            f"}}  // namespace {pkg}\n#endif\n")
    return text, list(dict.fromkeys(includes))


def _struct(name: str, members: str) -> str:
    return (f"template<class ContainerAllocator>\nstruct {name}_\n{{\n"
            f"  using Type = {name}_<ContainerAllocator>;\n"
            f"  using SharedPtr = std::shared_ptr<{name}_<ContainerAllocator>>;\n"
            f"  using ConstSharedPtr = std::shared_ptr<{name}_<ContainerAllocator> const>;\n"
            f"  using UniquePtr = std::unique_ptr<{name}_<ContainerAllocator>>;\n"
            f"  using ConstUniquePtr = std::unique_ptr<{name}_<ContainerAllocator> const>;\n"
            f"  using WeakPtr = std::weak_ptr<{name}_<ContainerAllocator>>;\n"
            f"  using ConstWeakPtr = std::weak_ptr<{name}_<ContainerAllocator> const>;\n"
            f"  {name}_();\n  explicit {name}_(const ContainerAllocator & allocator);\n"
            f"  bool operator==(const {name}_ & other) const;\n  bool operator!=(const {name}_ & other) const;\n"
            f"{members}}};\nusing {name} = {name}_<std::allocator<void>>;\n")


def _ros2_nested(base: str, pkg: str) -> tuple[str, str | None]:
    owner, _, type_name = base.rpartition("/")
    owner, type_name = _ROS1_BUILTINS.get(base, (owner or pkg, type_name))
    return f"{owner}::msg::{type_name}_<ContainerAllocator>", f"{owner}/msg/{snake(type_name)}.hpp"


def members(section: str, pkg: str, nested: Callable[[str, str], tuple[str, str | None]] = _ros2_nested,
            fixed_array: str = "std::array", field_types: bool = False) -> tuple[str, list[str]]:
    """C++ members (fields and constants) of one section of a definition, and the headers of the
    nested types; `nested(type, pkg)` is the C++ type of a non-primitive field and its header;
    `field_types`: each field's type also named `_<field>_type`, as ROS 1's gencpp does."""
    lines, includes = [], []
    for raw in section.splitlines():
        text = raw.split("#", 1)[0].strip() if '"' not in raw and "'" not in raw else raw.strip()
        match = _FIELD.match(text)
        if match is None:
            continue
        base = match.group("type")
        if base in _PRIMITIVES:
            cpp = _PRIMITIVES[base]
        else:
            cpp, include = nested(base, pkg)
            includes += [include] if include else []
        if match.group("constant") is not None and base in _PRIMITIVES:
            lines.append(_constant(cpp, match.group("name"), match.group("constant").strip()))
            continue
        if match.group("array"):
            cpp = f"{fixed_array}<{cpp}, {match.group('n')}>" if match.group("n") and not match.group("size") \
                else f"std::vector<{cpp}>"
        name = match.group("name")
        lines.append(f"  typedef {cpp} _{name}_type;\n  _{name}_type {name};\n" if field_types else f"  {cpp} {name};\n")
    return "".join(lines), includes


def _constant(cpp: str, name: str, value: str) -> str:
    if cpp == "std::string":
        quoted = value if value[:1] in "\"'" else f'"{value}"'
        return f"  static constexpr const char * {name} = \"{quoted[1:-1]}\";\n"
    if cpp == "bool":
        value = "true" if value.lower() in ("true", "1") else "false"
    return f"  static constexpr {cpp} {name} = {value};\n"


def _write_folder(folder: Path, files: dict[str, str]) -> None:
    """Write the headers into a fresh folder, then move it into place (another process may race)."""
    folder.parent.mkdir(parents=True, exist_ok=True)
    staging = Path(tempfile.mkdtemp(dir=folder.parent, prefix=".partial-"))
    for name, text in files.items():
        target = staging / name
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_text(text)
    (staging / ".done").write_text("")
    try:
        os.rename(staging, folder)
    except OSError:  # already there: written by another process
        _remove(staging)


def _remove(folder: Path) -> None:
    for path in sorted(folder.rglob("*"), key=lambda p: len(p.parts), reverse=True):
        path.rmdir() if path.is_dir() else path.unlink()
    folder.rmdir()
