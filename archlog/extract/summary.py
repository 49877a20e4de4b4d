"""What an extractor recovers from one node executable, before it is placed in a configuration."""

from __future__ import annotations

from dataclasses import dataclass, field

from archlog.values import Value

PORT_KINDS = (
    "publisher", "subscriber", "service_server", "service_client",
    "action_server", "action_client", "param_read", "param_write", "timer",
)


PARAM_TYPES = ("bool", "integer", "double", "string", "byte_array", "bool_array", "integer_array", "double_array",
               "string_array")


@dataclass(frozen=True)
class ParamSpec:
    """What the code says about a parameter it declares or reads, beyond its name and default."""

    type: str = ""  # one of PARAM_TYPES when the declaration fixes it (ROS 2), else ""
    required: bool = False  # declared (or, rospy, read) without any default: the node needs it set
    read_only: bool = False
    bounds: tuple[tuple[str, str], ...] = ()  # (">=", "0.0"), ("<=", "1.0"), (">", ...), ("<", ...)
    choices: tuple[str, ...] = ()  # the values it accepts, when a validator lists them
    declared: bool = False  # a ROS 2 declaration (the node accepts values only of what it declares)


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
    also: tuple[tuple[Value, str | None], ...] = ()  # further conditions that must hold too (enclosing branches)
    info_of: Value | None = None  # image_transport: the image topic (as written) whose remapped sibling this is
    after_tf: tuple[str, ...] = ()  # the node creates it only after these transform waits (TransformWait.id) end
    type_of: tuple[Value, ...] = ()  # models: it carries the type the publishers of these topics (as written) give
    optional: bool = False  # an input the node works without (a model's `optional: true`)
    infrastructure: str = ""  # a built-in port of the client library: its group (system/infrastructure.py)
    param: ParamSpec | None = None  # param_read: what the declaration says beyond the default


@dataclass(frozen=True)
class Site:
    """A port's call in the source: publish calls and state writes name the port they belong to
    (a publisher, or the timer, subscriber or service whose callback reaches them) by its site."""

    file: str
    line: int


TRIGGERS = ("timer", "loop", "callback", "startup", "unknown")
# state values: what a guard tests and what a write makes true; "?" is a value not known statically
STATE_VALUES = ("true", "false", "set", "unset", "empty", "nonempty", "?")


@dataclass(frozen=True)
class Guard:
    """A condition on every path to a publish: state variable `var` must hold `value`
    (true/false, set/unset for a pointer or None, empty/nonempty for a container, or a constant)."""

    var: str
    value: str
    file: str
    line: int


@dataclass(frozen=True)
class Publish:
    """One publish call, one way it is reached: a timer or loop, the callback of `source` (a
    subscriber or service port), start-up code, or unknown; with the guards on that path."""

    publisher: Site | None
    file: str
    line: int
    trigger: str
    source: Site | None = None
    guards: tuple[Guard, ...] = ()
    period: Value | None = None  # a loop's period in seconds (trigger "loop")
    decided: bool = False  # its guards are all that decides whether this path reaches the call (python's walk)


@dataclass(frozen=True)
class StateWrite:
    """A state variable set to `value`: by the callback of `source`, or at start-up (initial
    value, constructor) when `source` is None."""

    var: str
    value: str
    source: Site | None
    file: str
    line: int
    decided: bool = False  # every path to it writes it, once per callback or at start-up (python's walk)


@dataclass(frozen=True)
class Transform:
    """A transform a node broadcasts on tf, from frame `parent` to frame `child` (as written: a frame or a
    parameter naming it). With `after`, only once the node has received a message on one of those
    topics (as written); with `condition`, only when it holds (as a port's)."""

    parent: Value
    child: Value
    file: str
    line: int
    after: tuple[Value, ...] = ()
    condition: tuple[Value, str | None] | None = None


@dataclass(frozen=True)
class TransformWait:
    """A node blocks until tf can transform frame `source` into frame `target` (costmap_2d's
    constructor does); ports marked with `id` in their `after_tf` are created only after that."""

    id: str
    target: Value
    source: Value
    file: str
    line: int
    after_tf: tuple[str, ...] = ()  # the waits that come before this one


@dataclass(frozen=True)
class PluginSlot:
    """Where a node loads pluginlib classes its parameters choose (node models only): the class named
    by parameter `param`, its namespace `namespace`/the class's own name (as move_base's planners), or,
    with `listed`, every {name, type} element of the list `param`, each in `namespace`/name (as a
    costmap's layers). `default` is what the node uses when the parameter is not set: a class name,
    or a list of {name, type, if} entries."""

    param: str
    namespace: str
    listed: bool
    default: object
    file: str
    line: int
    after_tf: tuple[str, ...] = ()  # the node loads these plugins only after these transform waits end


@dataclass(frozen=True)
class LoadedNodelet:
    """A nodelet an executable loads into its own process (nodelet::Loader::load): the plugin
    (pkg/Type), the nodelet's name (a FullNodeName when built from ros::this_node::getName()) and
    the remappings given with it, as written; its ports are the executable's (system/nodelets.py)."""

    plugin: Value
    name: Value
    remaps: tuple[tuple[Value, Value], ...]
    file: str
    line: int


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
    publishes: list[Publish] = field(default_factory=list)  # behavior: how each publish call is reached
    writes: list[StateWrite] = field(default_factory=list)
    plugins: tuple[PluginSlot, ...] = ()
    loads: list[LoadedNodelet] = field(default_factory=list)  # nodelets run in this process
    # (file, line) of each call creating pluginlib classes whose code is not read (extract/cpp/plugin_loads.py)
    plugin_loads: list[tuple[str, int]] = field(default_factory=list)
    # tf (node models): what it broadcasts, with `tf_declared` when that is all it broadcasts (besides the
    # transforms of the robot description parameter `tf_description`, or of its command line with
    # `tf_args`, as robot_state_publisher and static_transform_publisher), and what it waits for
    transforms: tuple[Transform, ...] = ()
    tf_waits: tuple[TransformWait, ...] = ()
    tf_declared: bool = False
    tf_description: str | None = None
    tf_args: bool = False
    tf_unknown: bool = False  # its description, arguments or gazebo plugins leave what it broadcasts unknown
    argv_ports: tuple[tuple[str, dict, str], ...] = ()  # models: (kind, entry, file) named from the command line
    valued_options: tuple[str, ...] = ()  # models: command-line options that take a value (not a positional word)
    # the ROS version (1 or 2) its source uses (rospy/roscpp, rclpy/rclcpp) or its model describes; None: unknown
    ros: int | None = None
    # built-in port groups (models/infrastructure/) beyond every node's that its code asks for (a lifecycle
    # node, enable_logger_service), and the default ones it turns off (start_parameter_services=False)
    infrastructure: tuple[str, ...] = ()
    without: tuple[str, ...] = ()
    others: list[NodeSummary] = field(default_factory=list)  # further nodes the same process creates (rclpy)
    # why the node may declare or read parameters under names not known statically (allow_undeclared_parameters,
    # a read of every parameter under a prefix, dynamic_reconfigure) as "file:line: reason"; "" when it does not
    params_dynamic: str = ""
