"""Every relation archlog produces: name, typed columns, meaning. docs/facts.md is generated from here.

Column types: `id` (a port or element id such as "p3" or "e7"), `name` (a resolved ROS graph
name), `type` (a message type "pkg/Name"), `str`, `int`. Any `name`, `type` or `str` column may
hold an unknown value instead: a term `unknown(N)` described by the `unknown_value` relation, and
written `?(expr)` wherever archlog prints or writes values.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Column:
    name: str
    type: str
    doc: str


@dataclass(frozen=True)
class Relation:
    name: str
    columns: tuple[Column, ...]
    doc: str
    group: str
    source: str = ""  # derived relations: the rule file (under archlog/rules/builtin/) that defines it

    @property
    def arity(self) -> int:
        return len(self.columns)


def _rel(group: str, name: str, doc: str, *cols: tuple[str, str, str]) -> Relation:
    return Relation(name, tuple(Column(*c) for c in cols), doc, group)


_PORT = ("port", "id", "the port's id; `location` gives its file and line")
_NODE = ("node", "name", "the node instance's resolved name")

RELATIONS: tuple[Relation, ...] = (
    _rel("workspace", "package", "A ROS package found in the indexed paths or installed share dirs.",
         ("pkg", "str", "package name"), ("path", "str", "its folder")),
    _rel("workspace", "executable", "A node executable a package builds or installs.",
         ("pkg", "str", "package name"), ("exe", "str", "executable name (the launch `type`)"),
         ("lang", "str", "cpp or python"), ("file", "str", "main source file")),
    _rel("workspace", "message_type", "A message, service or action definition that was found.",
         ("type", "type", "full type name pkg/Name"), ("kind", "str", "msg, srv or action"),
         ("file", "str", "the definition file")),
    _rel("configuration", "node", "A node instance of the system configuration.",
         _NODE, ("pkg", "str", "package"), ("exe", "str", "executable"),
         ("elem", "id", "the launch element (or executable, for a rosrun configuration) that creates it")),
    _rel("configuration", "conditional", "A node kept although its if/unless (or an enclosing one) could not be "
         "resolved statically.", ("elem", "id", "the node's element"), ("condition", "str", "the condition and why")),
    _rel("configuration", "condition_settled", "A conditional node each of whose undecided conditions depends on one "
         "launch argument of unknown value alone (extract/launch/conditions.py): `condition_value` says when it runs.",
         ("elem", "id", "the node's element")),
    _rel("configuration", "condition_value", "A value of an unknown launch argument with which a settled conditional "
         "node's conditions may all hold (of the values tried: those the conditions on the argument are written with, "
         "the booleans, and `(any other value)`). A node with no row for an argument it depends on never runs.",
         ("elem", "id", "the node's element"), ("arg", "str", "the argument (its name and a number for each one)"),
         ("value", "str", "the value")),
    _rel("configuration", "condition_on", "A launch argument of unknown value that a settled conditional node's "
         "conditions depend on.", ("elem", "id", "the node's element"), ("arg", "str", "as in condition_value")),
    _rel("configuration", "ros2_node", "A node instance that runs on ROS 2: a ROS 2 launch file starts it, or, with "
         "no launch file, its package is built with ament.", _NODE),
    _rel("configuration", "standalone", "A node instance of the configuration without a launch file (every executable "
         "once, each started by itself): which of them run together is not known.",
         ("elem", "id", "the node's element")),
    _rel("configuration", "launch_hole", "A part of the configuration archlog could not read (an include skipped, a "
         "launch action not interpreted or skipped): the nodes it starts are not known; the report is partial.",
         ("hole", "id", "its id; `location` gives the launch file and line"), ("reason", "str", "why")),
    _rel("configuration", "plugin_hole", "Where a node instance creates pluginlib classes chosen at run time whose "
         "code archlog does not read (no node model's `plugins:` slot describes them): the ports they create "
         "are not known; the report is partial.",
         ("hole", "id", "its id; `location` gives the file and line of the call"), _NODE, ("reason", "str", "why")),
    _rel("configuration", "outside_port", "A name a modelled executable the configuration does not run would provide "
         "(system/outside.py): a package the configuration runs depends on it, or, without a launch file, any.",
         ("kind", "str", "publisher, service_server or action_server"), ("name", "name", "resolved under its default "
         "node name in the root namespace"), ("type", "str", "its type, in each ROS version's spelling"),
         ("provider", "str", "package/executable")),
    _rel("configuration", "node_name_unknown", "A node instance whose name is not known statically (neither the "
         "launch file nor the code gives one archlog can read): the executable's name stands in for it.",
         ("elem", "id", "the node's element")),
    _rel("configuration", "nodelet", "A node instance that loads a nodelet plugin (nodelet load/standalone).",
         _NODE, ("plugin", "str", "plugin type pkg/Name"), ("manager", "str", "manager node as written, or empty")),
    _rel("configuration", "included_through", "An <include> a node's element was loaded through.",
         ("elem", "id", "the node's element"), ("include", "id", "an <include> element"),
         ("depth", "int", "1 for the outermost include")),
    _rel("configuration", "node_source", "Where a node instance's ports were recovered from.",
         _NODE, ("origin", "str", "cpp, python or model")),
    _rel("configuration", "node_incomplete", "A node instance whose source could not be fully read (it does not "
         "parse or compile), so some of its ports may be missing.", _NODE, ("reason", "str", "the first problem")),
    _rel("configuration", "remap", "A remapping applied to a node instance, both sides resolved in its namespace.",
         ("elem", "id", "the `<remap>` element (or node args) that declares it"), _NODE,
         ("from", "name", "resolved source name"), ("to", "name", "resolved target name")),
    _rel("configuration", "remap_declared", "A <remap> outside any <node>, resolved in its scope's namespace "
         "(whether or not a node follows it).", ("elem", "id", "the <remap> element"),
         ("from", "name", "resolved source name"), ("to", "name", "resolved target name")),
    _rel("configuration", "param", "A parameter value set by the configuration.",
         ("param", "name", "resolved parameter name"), ("value", "str", "value as text"),
         ("elem", "id", "the element that sets it")),
    _rel("configuration", "node_namespace", "The namespace a node instance lives in.",
         _NODE, ("ns", "name", "its namespace: /robot1 for /robot1/driver, / for /driver")),
    _rel("configuration", "name_namespace", "The namespace part of every resolved name the facts use (nodes, "
         "topics, services, actions, parameters, remaps).",
         ("name", "name", "a resolved name"), ("ns", "name", "its namespace: /a/b for /a/b/c, / for /c")),
    _rel("configuration", "name_leaf", "The last segment of every resolved name the facts use.",
         ("name", "name", "a resolved name"), ("leaf", "str", "its last segment: c for /a/b/c")),
    _rel("configuration", "param_scope", "Whose parameter a parameter name is: a node's private parameter (~name) "
         "or a global one (any other namespace).",
         ("param", "name", "a parameter set or used"),
         ("scope", "name", "the node whose private namespace holds it (the innermost one), or \"global\"")),
    _rel("ports", "publisher", "A node instance publishes a topic.",
         _PORT, _NODE, ("topic", "name", "resolved, remapped topic"), ("type", "type", "message type")),
    _rel("ports", "subscriber", "A node instance subscribes to a topic.",
         _PORT, _NODE, ("topic", "name", "resolved, remapped topic"), ("type", "type", "message type")),
    _rel("ports", "service_server", "A node instance provides a service.",
         _PORT, _NODE, ("service", "name", "resolved, remapped service"), ("type", "type", "service type")),
    _rel("ports", "service_client", "A node instance calls a service.",
         _PORT, _NODE, ("service", "name", "resolved, remapped service"), ("type", "type", "service type")),
    _rel("ports", "action_server", "A node instance serves an action.",
         _PORT, _NODE, ("action", "name", "resolved, remapped action namespace"), ("type", "type", "action type")),
    _rel("ports", "action_client", "A node instance is a client of an action.",
         _PORT, _NODE, ("action", "name", "resolved, remapped action namespace"), ("type", "type", "action type")),
    _rel("ports", "param_read", "A node instance reads or declares a parameter (in its code, or in the "
         "generate_parameter_library definition its executable links, located at the parameter's key).",
         _PORT, _NODE, ("param", "name", "resolved parameter name"), ("default", "str", "default value, or unknown")),
    _rel("ports", "param_write", "A node instance sets (or deletes) a parameter.",
         _PORT, _NODE, ("param", "name", "resolved parameter name"), ("value", "str", "value set, or 'delete'")),
    _rel("ports", "param_type", "The type a ROS 2 declaration gives a parameter (of its default, its template "
         "argument or a ParameterType); a value of another type makes the node throw at start-up.",
         _PORT, ("type", "str", "bool, integer, double, string, byte_array, bool_array, integer_array, "
                 "double_array or string_array")),
    _rel("ports", "param_required", "A parameter declared (ROS 2) or read (rospy.get_param, outside a try block) "
         "without any default: the node fails, or holds no value, unless the configuration sets it.", _PORT),
    _rel("ports", "param_read_only", "A parameter its declaration makes read-only (ParameterDescriptor read_only in "
         "rclpy or rclcpp, read_only: true in a generate_parameter_library definition).",
         _PORT),
    _rel("ports", "param_bound", "A bound its declaration puts on a parameter's value (a ParameterDescriptor's "
         "floating_point_range or integer_range, rclpy or rclcpp; a generate_parameter_library validator: bounds, "
         "lower_bounds, upper_bounds, gt, lt, gt_eq, lt_eq); ROS 2 rejects a value outside it at start-up.",
         _PORT, ("op", "str", ">=, <=, > or <"), ("value", "str", "the bound, a number as written")),
    _rel("ports", "param_choice", "A value a parameter's declaration accepts, when its validator lists them (the "
         "parameter takes one of the listed values: generate_parameter_library's one_of).", _PORT,
         ("value", "str", "an accepted value as text")),
    _rel("ports", "timer", "A periodic trigger in a node: a timer or a loop rate (for behavioral rules).",
         _PORT, _NODE, ("period", "str", "period in seconds as written or folded, or unknown")),
    _rel("ports", "queue_size", "The message queue of a ROS 1 publisher or subscriber.",
         _PORT, ("size", "str", "a number; 'unbounded' (0 in roscpp, None in rospy, a rospy Subscriber's default); "
                 "'unset' (a rospy Publisher without queue_size publishes synchronously)")),
    _rel("ports", "qos", "A QoS policy of a ROS 2 publisher or subscriber.",
         _PORT, ("policy", "str", "history, depth, reliability, durability, deadline, lifespan, liveliness, "
                 "liveliness_lease_duration, or profile"), ("value", "str", "the policy's value: keep_last, keep_all, "
                 "reliable, best_effort, volatile, transient_local, automatic, manual_by_topic, system_default, a "
                 "depth, a duration in seconds, or a preset name (`?(expr)` when unknown)")),
    _rel("ports", "qos_duration", "A QoS duration policy of a ROS 2 publisher or subscriber as a number "
         "(absent: infinite, the default).",
         _PORT, ("policy", "str", "deadline, lifespan or liveliness_lease_duration"),
         ("microseconds", "int", "the duration in microseconds, at most 2147483647 (about 36 minutes)")),
    _rel("ports", "optional_port", "A subscriber its node works without (a model marks it `optional: true`: an "
         "input users may send, such as a reset); AL103, AL104 and AL601 do not report it as unfed.", _PORT),
    _rel("ports", "infrastructure_port", "A port every ROS 2 node of its kind has because of its client library, not "
         "because its code creates it: /rosout, /parameter_events, the parameter services, a lifecycle node's "
         "services and transition_event, the logger services (archlog/models/infrastructure/ros2.yaml). Rules and "
         "reports may hide them.", _PORT, ("group", "str", "rosout, parameter_events, parameter_services, "
                                            "type_description, lifecycle or logger_service")),
    _rel("ports", "alternative_names", "A port whose name is one of several at run time (a ternary, if/else); "
         "each alternative is its own row of the port's relation.", _PORT, ("count", "int", "how many alternatives")),
    _rel("ports", "port_source_name", "A port's name resolved in the node's namespace, before remapping.",
         _PORT, ("name", "name", "resolved name before remaps")),
    _rel("ports", "handle_namespace", "A ROS 1 port created on a NodeHandle with a namespace of its own: that "
         "namespace resolved in the node's, before remapping (roscpp remaps it like any name, so a remap of it moves "
         "every port of the handle).", _PORT, ("namespace", "name", "the handle's resolved namespace")),
    _rel("ports", "port_name_param", "A port whose name is the value of a parameter (with a default, or a model's "
         "`{param: ...}`).", _PORT, ("param", "name", "the resolved parameter name")),
    _rel("configuration", "param_topic", "A parameter the configuration sets in a node's private namespace that names "
         "a topic: its last segment ends in `topic`, or some port takes its name from a parameter of that last "
         "segment, and its value is a graph name.", ("param", "name", "resolved parameter name"), _NODE,
         ("topic", "name", "the value resolved as the node would resolve a topic name")),
    _rel("configuration", "param_of", "The node instance a parameter the configuration sets is for (the innermost "
         "node whose private namespace holds it; in ROS 2 every parameter given to a node), and the name the node "
         "knows it by.", ("param", "name", "resolved parameter name"), _NODE,
         ("local", "str", "the name relative to the node: dotted in ROS 2 (`controller.max_vel`), a relative name "
          "in ROS 1")),
    _rel("configuration", "param_value_type", "The type of the value the configuration sets (as the node receives "
         "it: a YAML or launch value typed as rcl and launch type them).", ("param", "name", "resolved parameter "
         "name"), ("type", "str", "bool, integer, double, string, or bool_array ... string_array; no row for a "
                   "mapping, an empty or mixed list, or an unknown value")),
    _rel("configuration", "params_dynamic", "A node instance that may declare or read parameters under names not "
         "known statically (allow_undeclared_parameters, automatically_declare_parameters_from_overrides, a read "
         "of every parameter under a prefix, a dynamic_reconfigure server, a pluginlib class): parameter rules "
         "treat its parameters as partly unknown.", _NODE, ("reason", "str", "file:line: why")),
    _rel("configuration", "param_set_unknown", "Where the configuration sets parameters archlog cannot know (a "
         "parameter file or a parameter name not known statically, a <param> or <rosparam> skipped): any "
         "parameter may be set there.", ("elem", "id", "the element"), ("reason", "str", "why")),
    _rel("derived", "param_near", "A parameter the configuration sets for a node that neither declares nor reads it "
         "(nor a namespace above it), and a parameter name that node does declare or read whose segment distance "
         "is below the near-miss threshold; computed only for nodes whose parameter names are all known.",
         ("param", "name", "the parameter set"), ("candidate", "name", "a parameter its node declares or reads"),
         ("distance", "int", "segment-aware Damerau-Levenshtein distance, in thousandths")),
    _rel("ports", "private_name", "A name some port uses that lies in a node instance's private namespace "
         "(/robot/amcl/particlecloud for /robot/amcl).", ("name", "name", "the name"), _NODE),
    _rel("behavior", "publish_call", "A call that publishes on a publisher port (`location` gives its file:line).",
         ("call", "id", "the publish call"), _NODE, ("pub", "id", "the publisher port it uses")),
    _rel("behavior", "publish_trigger", "One way a publish call is reached (a call may have several).",
         ("call", "id", "the publish call"), ("trigger", "str", "timer, loop, callback, startup or unknown"),
         ("source", "id", "the timer, subscriber or service port whose callback reaches it; `none` otherwise")),
    _rel("behavior", "publish_guard", "A state condition on every path to a publish call.",
         ("call", "id", "the publish call"), ("var", "str", "the state variable"),
         ("value", "str", "true, false, set, unset, empty, nonempty or a constant"),
         ("guard", "id", "the condition, for its location")),
    _rel("behavior", "state_write", "A state variable set by a callback or at start-up.",
         ("write", "id", "the assignment, for its location"), _NODE, ("var", "str", "the state variable"),
         ("value", "str", "the value it gets: true, false, set, unset, empty, nonempty, a constant, or ? when unknown"),
         ("source", "id", "the subscriber or service port whose callback writes it; `none` at start-up")),
    _rel("behavior", "decided", "A publish call or state write that its trigger and guards alone decide: every "
         "condition on every path to it is one of its guards (or, for a write, there is none), all paths to a call "
         "have the same guards. Only Python's walk tells; a call or write without it may depend on more.",
         ("id", "id", "the publish call or the state write")),
    _rel("behavior", "loop_period", "The period of the loop a periodic publish call sits in.",
         ("call", "id", "the publish call"), ("period", "str", "seconds, or unknown")),
    _rel("transforms", "tf_broadcast", "A transform a node instance broadcasts on tf (its model's `tf_broadcasts`, "
         "the joints of its robot description, its static_transform_publisher arguments).",
         ("id", "id", "the broadcast; `location` gives the model entry, the joint or the launch element"), _NODE,
         ("parent", "str", "the parent frame (without a leading slash)"), ("child", "str", "the child frame")),
    _rel("transforms", "tf_broadcast_after", "A broadcast that starts only once its node has received a message on "
         "one of these topics (amcl's map -> odom after a scan); a broadcast without rows starts at once.",
         ("id", "id", "the broadcast"), ("topic", "name", "a topic that starts it (resolved, remapped)")),
    _rel("transforms", "tf_declared", "A node instance whose broadcasts archlog knows completely: the tf_broadcast rows "
         "are all it broadcasts. Any other node that publishes /tf or /tf_static may broadcast anything.", _NODE),
    _rel("transforms", "tf_unknown", "A node instance that may broadcast transforms archlog cannot know: its robot "
         "description cannot be read statically, its static_transform_publisher arguments name no transform, or the "
         "description it spawns loads a gazebo plugin whose broadcasts are not modelled.", _NODE),
    _rel("transforms", "tf_wait", "A node instance blocks until tf can transform one frame into another (costmap_2d "
         "waits in its constructor for global_frame <- robot_base_frame); frames bound to its parameters.",
         ("id", "id", "the wait; `location` gives the model entry"), _NODE,
         ("target", "str", "the frame transformed into"), ("source", "str", "the frame transformed from")),
    _rel("transforms", "tf_wait_after", "A wait that comes only after another one has ended (move_base builds its "
         "local costmap after its global one).", ("wait", "id", "the later tf_wait"), ("before", "id", "the earlier one")),
    _rel("transforms", "port_after_tf", "A port its node creates only after a wait ends: it exists in the code, but at "
         "run time only once the transform is available.", _PORT, ("wait", "id", "the tf_wait")),
    _rel("provenance", "location", "Where a port, launch element or node comes from.",
         ("id", "id", "port or element id"), ("file", "str", "file, relative to the first indexed path when inside it"),
         ("line", "int", "1-based line"), ("column", "int", "1-based column, 0 when unknown")),
    _rel("provenance", "unknown_value", "A value static analysis could not know, and where it was met.",
         ("value", "id", "the unknown value: the term unknown(N) other relations use in rules, written "
          "?(expr) in output"), ("expr", "str", "the expression"),
         ("file", "str", "file"), ("line", "int", "line")),
    _rel("provenance", "unknown_pattern", "An unknown name of which a part is known (`ns + \"/scan\"`): "
         "resolved as the name would be, it starts with `prefix` and ends with `suffix`; an unknown name without "
         "this row might be any name.",
         ("value", "id", "the unknown name, a term unknown(N)"),
         ("prefix", "str", "what the resolved name starts with (\"\" when unknown)"),
         ("suffix", "str", "what it ends with (\"\" when unknown)")),
    _rel("derived", "may_name", "An unknown name with known parts (unknown_pattern) and a name some port or remap "
         "uses that fits them: the unknown name might be it.", ("value", "id", "the unknown name"),
         ("name", "name", "the name it might be")),
    _rel("derived", "near_name",
         "Two names whose segment distance is below the near-miss threshold, where one may be a broken link: a "
         "name someone waits on that nothing provides (subscribed and not published, called and not served, an "
         "action used and not served) with a name of that kind's providers; or a topic published to nobody with a "
         "connected topic (published and subscribed) that a subscriber of a compatible type uses. Names nobody "
         "waits on (a server nobody calls, two unheard publishers) are not paired.",
         ("a", "name", "a name"), ("b", "name", "another name"),
         ("distance", "int", "segment-aware Damerau-Levenshtein distance, in thousandths")),
    _rel("derived", "near_scope",
         "For a near_name pair: how far apart their namespaces are, seen from the first name.",
         ("a", "name", "a name"), ("b", "name", "another name"),
         ("up", "int", "namespace levels above a's namespace to the nearest namespace a and b share; 0 when "
          "both are in the same namespace")),
)

BY_NAME: dict[str, Relation] = {r.name: r for r in RELATIONS}


def _derived(source: str, name: str, doc: str, *cols: tuple[str, str, str]) -> Relation:
    return Relation(name, tuple(Column(*c) for c in cols), doc, "rules", source)


_PRELUDE = "prelude.lp"
_AL601 = "AL601_required_input_unreachable.lp"
_AL401 = "AL401_unused_remap.lp"
_AL301 = "AL301_duplicate_node_name.lp"
_AL701 = "AL701_transform_never_available.lp"
_AL403 = "AL403_parameter_never_declared.lp"
_AL405 = "AL405_parameter_out_of_range.lp"
_SUB = ("sub", "id", "the subscriber port")

# Relations the shipped rules derive that Python code reads from the grounded program (reports,
# finding lists) or that the guide offers to rule writers. Not facts: `archlog facts` does not
# export them, and a rule may not add rows to them from facts of its own. A finding predicate of a
# shipped rule (near_miss/9, ...) is declared by that rule's `finding:` header instead.
DERIVED: tuple[Relation, ...] = (
    _derived(_PRELUDE, "is_unknown", "A value static analysis could not know (a term unknown(N)).",
             ("value", "id", "the unknown term")),
    _derived(_PRELUDE, "alternative_instances", "Two node instances started by themselves (standalone), or whose "
             "conditions exclude each other (exclusive_conditions): alternatives that are not known to run together "
             "(AL101, AL103, AL202 and AL301 do not pair them).",
             ("a", "id", "a node's element"), ("b", "id", "another node's element")),
    _derived(_PRELUDE, "exclusive_conditions", "Two conditional node instances whose conditions on one launch argument "
             "of unknown value hold for no common value (condition_value): they never run together.",
             ("a", "id", "a node's element"), ("b", "id", "another node's element")),
    _derived(_PRELUDE, "alternative_nodes", "Two nodes whose instances are alternatives (alternative_instances).",
             ("a", "name", "a node"), ("b", "name", "another node")),
    _derived(_PRELUDE, "port_node", "The node instance a port of any kind belongs to.", _PORT, _NODE),
    _derived(_PRELUDE, "published", "A topic some publisher uses.", ("topic", "name", "the topic")),
    _derived(_PRELUDE, "subscribed", "A topic some subscriber uses.", ("topic", "name", "the topic")),
    _derived(_PRELUDE, "provided", "A service some server provides.", ("service", "name", "the service")),
    _derived(_PRELUDE, "connected", "A topic both published and subscribed.", ("topic", "name", "the topic")),
    _derived(_PRELUDE, "compatible", "Two message types used by ports that can meet: equal, or either one unknown.",
             ("a", "type", "a message type"), ("b", "type", "another one")),
    _derived(_PRELUDE, "dangling_sub", "A subscriber with no publisher on its (known) name nor on another of its "
             "alternative names; /tf and /tf_static are never dangling.",
             _PORT, _NODE, ("topic", "name", "the topic"), ("type", "type", "message type")),
    _derived(_PRELUDE, "dangling_pub", "A publisher with no subscriber on its (known) name nor on another of its "
             "alternative names.", _PORT, _NODE, ("topic", "name", "the topic"), ("type", "type", "message type")),
    _derived(_PRELUDE, "has_near", "A port that AL102 reports as a near miss (AL103 and AL104 leave it to AL102).",
             _PORT),
    _derived(_PRELUDE, "maybe_fed", "A topic some subscriber uses that a publisher of unknown name might publish: "
             "its name has no known parts, or they fit the topic, and its type is compatible.",
             ("topic", "name", "the topic"), ("type", "type", "the subscriber's message type")),
    _derived(_PRELUDE, "maybe_heard", "A topic some publisher uses that a subscriber of unknown name might hear "
             "(as maybe_fed, the other way).", ("topic", "name", "the topic"),
             ("type", "type", "the publisher's message type")),
    _derived(_PRELUDE, "params_unknown", "A node instance whose parameter names archlog does not know completely: "
             "opaque, a node model, a parameter read under an unknown name, or params_dynamic.", _NODE),
    _derived(_PRELUDE, "param_candidate", "For a configured parameter its node never declares or reads (AL403), the "
             "nearest parameter name the node does declare or read (param_near; ties: the first by name).",
             ("param", "name", "the parameter set"), ("candidate", "name", "the nearest declared one")),
    _derived(_AL403, "param_candidate_local", "An AL403 candidate's name relative to its node (the finding's "
             "`candidate` list).", ("param", "name", "the parameter set"), ("local", "str", "the candidate's name")),
    _derived(_AL403, "param_kept", "What a node keeps because a parameter was misnamed: the candidate's default, and "
             "the topic a port named from it then uses (AL403's `kept` list).", ("param", "name", "the parameter set"),
             ("text", "str", "`scan_topic = 'scan' and subscribes /scan, which nothing publishes`")),
    _derived(_AL405, "param_choices_of", "The values a configured parameter's declaration accepts (AL405's `choices` "
             "list).", ("param", "name", "the parameter set"), ("value", "str", "an accepted value")),
    _derived(_PRELUDE, "opaque_node", "A node instance whose ports are not (all) known: no source or model, or "
             "incomplete extraction.", _NODE),
    _derived(_PRELUDE, "system_opaque", "Some node instance of the configuration is opaque."),
    _derived(_PRELUDE, "opaque_may_use", "An opaque node that might use a name archlog cannot see it use: the launch "
             "file remaps one of its names onto it, the name lies in its private namespace, or (extraction "
             "incomplete) its known ports use the name's type. That can be every name of a type for every opaque "
             "node using it, so it is grounded only when a query, a rule or an explanation names it; rules that ask "
             "whether some opaque node might use a name read opaque_may_name (or opaque_near).",
             _NODE, ("name", "name", "a topic, service or action name")),
    _derived(_PRELUDE, "opaque_may_name", "A name some opaque node might use (opaque_may_use, without saying which "
             "node).", ("name", "name", "a topic, service or action name")),
    _derived(_PRELUDE, "opaque_near", "A name a node has a port on and that an opaque node other than it might use "
             "(a rule about that port cannot conclude).", ("name", "name", "the name"), _NODE),
    _derived(_PRELUDE, "opaque_other", "An opaque node other than the port's own, for a port of a finding that names "
             "the uncertainty left (the `unseen` lists), when at most five nodes are opaque.", _PORT, _NODE),
    _derived(_PRELUDE, "opaque_many", "For a port of a finding that names the uncertainty left, how many nodes are "
             "opaque when there are more than five (they are then counted, not named).", _PORT,
             ("count", "int", "the number of opaque nodes")),
    _derived(_PRELUDE, "unread_part", "For a port of a finding that names the uncertainty left, a part of the "
             "configuration not read (launch_hole, plugin_hole) that may start what it misses.", _PORT,
             ("where", "str", "the part's file:line")),
    _derived(_PRELUDE, "uncertain_port", "The port (and its node) of a finding of AL103, AL104, AL201, AL203 or AL601, "
             "whose message names the opaque nodes it still depends on.", _PORT, _NODE),
    _derived(_PRELUDE, "outside_by", "A subscriber or client whose counterpart only a modelled node outside the "
             "configuration would provide (outside_port), and that node (AL106's `providers` list).",
             _PORT, ("provider", "str", "package/executable")),
    _derived(_PRELUDE, "unfed", "A subscriber whose topic nothing publishes, nor might publish (no publisher with an "
             "unknown name of a compatible type, no opaque node that might use the topic).", _SUB, _NODE,
             ("topic", "name", "the topic")),
    _derived(_PRELUDE, "group_input", "Alternative inputs: a guard only the callbacks of two or more inputs set, so "
             "the publish call needs one of them.", ("group", "id", "the guard, g(call, var, value)"), _SUB),
    _derived(_PRELUDE, "required_group", "An output every call of which needs one of a group of alternative inputs.",
             ("pub", "id", "the publisher port"), ("group", "id", "the group")),
    _derived(_PRELUDE, "qos_pair", "A publisher and a subscriber of one topic whose QoS is known, so their policies "
             "must be compatible for them to connect.", ("topic", "name", "the topic"),
             ("pub", "id", "the publisher port"), ("pub_node", "name", "its node"), _SUB,
             ("sub_node", "name", "its node")),
    _derived(_PRELUDE, "requires", "An output (publisher port) that every call publishing it publishes only after "
             "the input's callback ran.", ("pub", "id", "the publisher port"), _SUB),
    _derived(_PRELUDE, "required_topic", "A topic an output requires (`archlog behavior` lists them).",
             ("pub", "id", "the publisher port"), ("topic", "name", "the required input's topic")),
    _derived(_PRELUDE, "starved_input", "A required input that nothing in the configuration publishes.",
             ("topic", "name", "the input's topic"), _SUB, _NODE),
    _derived(_AL601, "starved_output", "A topic published only after a starved input (AL601's `outputs` list).",
             _SUB, ("topic", "name", "the output's topic")),
    _derived(_AL601, "silenced_node", "A node silenced downstream of a starved input (AL601's `silenced` list).",
             _SUB, _NODE),
    _derived(_AL601, "starved_alternative", "Another input of a starved input's group, none of which is published "
             "(AL601's `alternatives` list).", _SUB, ("topic", "name", "the alternative's topic")),
    _derived(_AL401, "remap_target", "A node an ineffective remap applies to (AL401's `applies` list).",
             ("elem", "id", "the remap"), _NODE),
    _derived(_AL401, "remap_user_before", "A node that uses an ineffective remap's name but is declared before it in "
             "the same file (AL401's `before` list).", ("elem", "id", "the remap"), _NODE),
    _derived(_AL401, "remap_user_outside", "A node that uses an ineffective remap's name outside its scope (AL401's "
             "`outside` list).", ("elem", "id", "the remap"), _NODE),
    _derived(_AL401, "remap_plugins", "Where a node an ineffective remap applies to creates pluginlib classes whose "
             "code is not read, at file:line (AL401's `loads` list: the finding is a note).", ("elem", "id", "the remap"),
             ("where", "str", "file:line of the plugin_hole")),
    _derived(_AL301, "clash_condition", "An undecided condition of one of two nodes with one name that archlog could "
             "not try (AL301's `when` list: the finding is a note).", ("elem", "id", "the later node's element"),
             ("condition", "str", "the condition and why it is undecided")),
    _derived(_AL601, "near_publisher", "A candidate for a starved input: a published near-miss name, or a topic of "
             "its type published to nobody (AL601's `near` list).", _SUB, ("topic", "name", "the candidate topic")),
    _derived(_AL701, "tf_live", "A broadcast that starts: at once, or after an input some node publishes (or might: "
             "an unknown or opaque publisher).", ("id", "id", "the tf_broadcast")),
    _derived(_AL701, "tf_unavailable", "A wait no broadcast in the configuration can ever end: no chain of live "
             "broadcasts links its two frames, every node that publishes tf declares what it broadcasts, and some "
             "node broadcasts a transform.",
             ("wait", "id", "the tf_wait")),
    _derived(_AL701, "tf_blocked_port", "A port created only after a wait that never ends: the code creates it, the "
             "running system never does.", _PORT, ("wait", "id", "the tf_wait")),
    _derived(_AL701, "tf_reached", "A frame the broadcasts that run link to an unavailable wait's target frame (AL701's "
             "`reached` list).", ("wait", "id", "the tf_wait"), ("frame", "str", "the frame")),
    _derived(_AL701, "tf_stalled", "A node whose broadcast would link an unavailable wait's two frames but never starts, "
             "as nothing publishes its input (AL701's `stalled` list).", ("wait", "id", "the tf_wait"), _NODE),
    _derived("AL102_near_miss_topic.lp", "near_also", "Another candidate as near as the one AL102 names for a "
             "dangling port (AL102's `also` list: the finding's related locations).", _PORT,
             ("other", "id", "the other candidate port")),
)

DERIVED_BY_NAME: dict[str, Relation] = {r.name: r for r in DERIVED}
