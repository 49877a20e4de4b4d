"""What an extractor recovers from one node executable, before it is placed in a configuration."""

from __future__ import annotations

from dataclasses import dataclass, field

from archlog.values import Value

PORT_KINDS = (
    "publisher", "subscriber", "service_server", "service_client",
    "action_server", "action_client", "param_read", "param_write", "timer",
)


@dataclass(frozen=True)
class Port:
    """One architecturally relevant API call, names as written (relative to its handle)."""

    kind: str
    name: Value
    type: Value
    file: str
    line: int
    column: int = 0
    handle_ns: Value = ""
    default: Value | None = None
    qos: tuple[tuple[str, str], ...] = ()
    queue: Value | None = None
    condition: tuple[Value, str | None] | None = None  # exists when the value equals the text (None: is set)


@dataclass
class NodeSummary:
    """The ports of one node executable and its default name (ros::init / rospy.init_node)."""

    package: str
    executable: str
    origin: str
    default_name: Value | None = None
    anonymous: bool = False
    ports: list[Port] = field(default_factory=list)
    incomplete: str | None = None
    name_file: str = ""
    name_line: int = 0
    namespace: Value = ""
