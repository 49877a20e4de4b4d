"""The roscpp walker: NodeHandles and their API calls, ROS libraries built on them, and values.

Recognised APIs are tables below, keyed by the callee's qualified class. Values are folded from
string literals, constants, std::string `+`, parameters read with defaults, and function
parameters whose call sites in the file agree (a per-function summary). When a file does not
compile, calls the AST lost are read from the tokens.
"""

from __future__ import annotations

from collections.abc import Callable
from fractions import Fraction
from pathlib import Path

import clang.cindex as ci

from archlog import sandbox
from archlog.diagnostics import Diagnostic
from archlog.extract.cpp.behavior import read_behavior
from archlog.extract.cpp.callers import FromCaller, function_keys
from archlog.extract.cpp.clang_ast import (
    SKIP,
    CursorKey,
    K,
    assignments,
    blank_comments,
    camera_info,
    default_constructed,
    is_rvalue,
    period,
    qualified,
    ros_type,
    template_arg_type,
    type_from_spelling,
    unquote,
    written_args,
)
from archlog.extract.cpp.handles import (
    IMAGE_FILTER,
    IMAGE_TRANSPORT,
    METHODS,
    NODE_HANDLE,
    NODELET_LAZY,
    Handles,
    is_handle_type,
)
from archlog.extract.cpp.loader import LOADER, loaded_nodelets
from archlog.extract.cpp.overrides import override_return
from archlog.extract.cpp.param_guards import Branches, initial_value, required
from archlog.extract.cpp.plugin_loads import creates_plugin, plugin_load_lines
from archlog.extract.cpp.rclcpp.durations import Durations
from archlog.extract.cpp.rclcpp.fallback import ros2_fallback, workspace_header_texts
from archlog.extract.cpp.rclcpp.type_adapters import adapted, adapters, not_interfaces
from archlog.extract.cpp.rclcpp.walker import RclcppWalker
from archlog.extract.cpp.rclcpp.wrappers import definitions, summaries
from archlog.extract.cpp.reach import Functions, build
from archlog.extract.cpp.result import FileResult
from archlog.extract.cpp.roscpp_fallback import roscpp_fallback
from archlog.extract.cpp.scope import Scope
from archlog.extract.cpp.string_edits import Edit, before, cut, edits, leading_cut, self_edit
from archlog.extract.summary import ParamSpec, Port
from archlog.values import Alternatives, FullNodeName, Namespace, ParamRef, Unknown, Value, alternatives, concat

PARAM_READS = {"param", "getParam", "getParamCached", "hasParam", "searchParam", "get", "getCached", "has", "search"}
PARAM_WRITES = {"setParam", "deleteParam", "set", "del"}
TIMERS = {"createTimer", "createWallTimer", "createSteadyTimer"}
# constructed objects that are ports: class -> (kind, fixed name or None, index of the name argument)
CONSTRUCTED: dict[str, list[tuple[str, str | None, int | None]]] = {
    "message_filters::Subscriber": [("subscriber", None, 1)],
    IMAGE_FILTER: [("subscriber", None, 1)],
    "actionlib::SimpleActionServer": [("action_server", None, 1)],
    "actionlib::ActionServer": [("action_server", None, 1)],
    "actionlib::SimpleActionClient": [("action_client", None, 1)],
    "actionlib::ActionClient": [("action_client", None, 1)],
    "tf::TransformBroadcaster": [("publisher", "/tf", None)],
    "tf2_ros::TransformBroadcaster": [("publisher", "/tf", None)],
    "tf2_ros::StaticTransformBroadcaster": [("publisher", "/tf_static", None)],
    "tf::TransformListener": [("subscriber", "/tf", None), ("subscriber", "/tf_static", None)],
    "tf2_ros::TransformListener": [("subscriber", "/tf", None), ("subscriber", "/tf_static", None)],
    "diagnostic_updater::Updater": [("publisher", "/diagnostics", None)],
    "dynamic_reconfigure::Server": [("service_server", "set_parameters", None),
                                    ("publisher", "parameter_descriptions", None),
                                    ("publisher", "parameter_updates", None)],
}
# constructed objects whose ports are named after a namespace argument: class -> (kind, suffix, type)
UNDER_NAMESPACE = {
    "interactive_markers::InteractiveMarkerServer": [
        ("publisher", "/update", "visualization_msgs/InteractiveMarkerUpdate"),
        ("publisher", "/update_full", "visualization_msgs/InteractiveMarkerInit"),
        ("subscriber", "/feedback", "visualization_msgs/InteractiveMarkerFeedback")],
}
FIXED_TYPES = {
    "/tf": "tf2_msgs/TFMessage", "/tf_static": "tf2_msgs/TFMessage", "/diagnostics": "diagnostic_msgs/DiagnosticArray",
    "set_parameters": "dynamic_reconfigure/Reconfigure",
    "parameter_descriptions": "dynamic_reconfigure/ConfigDescription",
    "parameter_updates": "dynamic_reconfigure/Config",
}


def walk(tu: ci.TranslationUnit, source: Path, shown: str, incomplete_ast: bool, cls: str | None = None,
         ros2: bool = False, workspace: tuple[str, ...] = (), graph: bool = False) -> FileResult:
    """Read one parsed file; with `cls`, only that class's methods (and free functions) count.
    `ros2`: the file is ROS 2 code (rclcpp/walker.py reads its API); `graph`: with its call graph."""
    walker = _Walker(source, shown, cls, ros2, workspace or (str(source.parent),))
    if graph:
        walker.result.graph, walker.functions = build(tu.cursor, walker.source, walker.scope.workspace_header)
        walker.result.graph.unsure = incomplete_ast
    walker.walk(tu.cursor)
    walker.result.classes = walker.scope.classes
    walker.members(walker.scope.members)
    if incomplete_ast:
        walker.token_fallback(tu)
    if ros2 and not_interfaces(walker.result.ports):
        texts = [sandbox.read_text(source, "source"), *workspace_header_texts(tu)]
        walker.result.ports = adapted(walker.result.ports, adapters(texts))
    walker.result.behavior = read_behavior(walker, walker.kept, walker.port_calls, walker.named_callbacks,
                                           sandbox.read_bytes(source, "source") if incomplete_ast else None)
    return walker.result


def _dynamic_params(owner: str, name: str, ref: ci.Cursor) -> str | None:
    """Why a roscpp call reads parameters by names the code does not spell (a dynamic_reconfigure server reads
    its config's, a pluginlib class its own, getParamNames lists them all), or None."""
    if ref.kind == K.CONSTRUCTOR and owner == "dynamic_reconfigure::Server":
        return "a dynamic_reconfigure server reads the parameters of its config"
    if creates_plugin(owner, name):
        return "a pluginlib class it loads reads parameters of its own"
    if owner in (NODE_HANDLE, "ros::param") and name in ("getParamNames", "searchParam", "search"):
        return f"{name}() reads parameters by names the code does not spell"
    return None


def _default_handle(owner: str) -> Value:
    """The namespace of a library object constructed without a handle: a dynamic_reconfigure
    server's is NodeHandle("~") of the process (in a nodelet, the manager's name, as
    ros::this_node::getName() is), the others' the node's."""
    return FullNodeName("~") if owner == "dynamic_reconfigure::Server" else ""


def _named_or_flag(type_: ci.Type) -> bool:
    """A type a name or a flag is passed as (a string, a character pointer, a bool)."""
    canonical = type_.get_canonical()
    return canonical.kind == ci.TypeKind.BOOL or "string" in canonical.spelling or "char" in canonical.spelling


def _made_class(call: ci.Cursor) -> str:
    """The class a make_shared<T>(...) / make_unique<T>(...) call constructs."""
    made = call.type.get_canonical().get_template_argument_type(0)
    return qualified(made.get_declaration()) if made.kind != ci.TypeKind.INVALID else ""


class _Walker:
    """Reads the ROS calls of one file (roscpp here; rclcpp through RclcppWalker when `ros2`)."""

    def __init__(self, source: Path, shown: str, cls: str | None = None, ros2: bool = False,
                 workspace: tuple[str, ...] = ()) -> None:
        self.source, self.file, self.ros2 = str(source), shown, ros2
        self.scope = Scope(self.source, workspace, cls)
        self.result = FileResult()
        self.param_vars: dict[CursorKey, Value] = {}
        self.bindings: dict[CursorKey, ci.Cursor] = {}  # parameter -> argument, while reading a call's callee
        self.call_sites: dict[CursorKey, list[ci.Cursor]] = {}
        self.spans: list[tuple[int, int]] | None = None
        self.loops: dict[CursorKey, ci.Cursor] = {}
        self.edits: dict[CursorKey, list[Edit]] = {}  # string variables' edits (string_edits.py)
        self.port_calls: dict[ci.Cursor, list[str]] = {}  # the call that made each port (behavior.py)
        self.named_callbacks: list[tuple[str, Port]] = []  # functions named in calls read from the tokens
        self.kept: list[ci.Cursor] = []
        self.functions = Functions()  # where the functions are (for the call graph of an executable's file)
        self.durations = Durations(self)
        self.handles = Handles(self)
        self.branches = Branches([])
        self.rclcpp = RclcppWalker(self, self.durations) if ros2 else None

    @staticmethod
    def key(decl: ci.Cursor | None) -> CursorKey:
        if decl is None or decl.location.file is None:
            return None
        return (decl.location.file.name, decl.location.line, decl.location.column)

    def in_main(self, cursor: ci.Cursor) -> bool:
        loc = cursor.location
        return loc.file is not None and loc.file.name == self.source

    def shown(self, cursor: ci.Cursor) -> str:
        """The file of a cursor as files are shown: a header relative to the folder the file is
        shown from."""
        path = cursor.location.file.name if cursor.location.file is not None else self.source
        if path == self.source:
            return self.file
        root = self.source[: len(self.source) - len(self.file)] if self.source.endswith(self.file) else ""
        return path[len(root):] if root and path.startswith(root) else path

    def unknown(self, cursor: ci.Cursor, why: str = "") -> Unknown:
        text = " ".join(t.spelling for t in cursor.get_tokens())[:120] or cursor.spelling
        return Unknown(text + (f" ({why})" if why else ""), self.shown(cursor), cursor.location.line)

    def seconds(self, expr: ci.Cursor, depth: int = 0) -> Fraction | None:
        """A duration in seconds (for behavior's timer periods)."""
        return self.durations.seconds(expr, depth)

    # -- traversal ------------------------------------------------------------------------
    def walk(self, root: ci.Cursor) -> None:
        cursors = [c for top in root.get_children() if self.in_main(top) for c in top.walk_preorder()
                   if self.in_main(c)]
        cursors += self.scope.header_code(cursors, self.key)
        for cursor in cursors:
            if cursor.kind == K.CALL_EXPR and cursor.referenced is not None:
                self.call_sites.setdefault(self.key(cursor.referenced.canonical), []).append(cursor)
            elif cursor.kind == K.CXX_FOR_RANGE_STMT:
                children = list(cursor.get_children())
                if len(children) >= 2 and children[0].kind == K.VAR_DECL:
                    self.loops[self.key(children[0])] = children[1]
        for cursor in cursors:
            if cursor.kind == K.CONSTRUCTOR:
                self.handles.member_inits(cursor)
        if self.rclcpp is not None:
            self.rclcpp.prepare(cursors)
        self.kept, self.spans = self.scope.relevant(cursors)
        self.branches = Branches(self.kept)
        calls = [c for c in self.kept if c.kind == K.CALL_EXPR]
        reads = [c for c in calls if c.spelling in PARAM_READS]  # first: a port's guard may test what they read
        for cursor in reads + [c for c in calls if c.spelling not in PARAM_READS]:
            self.call(cursor)
        if self.rclcpp is not None:
            self.rclcpp.wrapped(summaries(definitions(root, self.workspace_code), self.key, self.shown), calls,
                                self.scope.bound)
        self.record_call_sites(calls)

    def workspace_code(self, decl: ci.Cursor) -> bool:
        """A declaration in the file or in a header of the workspace."""
        return self.in_main(decl) or self.scope.workspace_header(decl)

    def from_call_sites(self, param: ci.Cursor, expr: ci.Cursor, evaluate: Callable[[ci.Cursor], Value],
                        what: str) -> Value:
        """The value all call sites in this file agree on for a parameter (a function summary)."""
        function = param.semantic_parent
        params = [p.spelling for p in function.get_arguments()] if function is not None else []
        index = params.index(param.spelling) if param.spelling in params else -1
        sites = self.call_sites.get(self.key(function.canonical), []) if index >= 0 else []
        found = {evaluate(args[index]) for site in sites if len(args := written_args(site)) > index}
        if len(found) == 1:
            return next(iter(found))
        if what == "NodeHandle" and len(found) > 1 and self.each_runs(sites) and \
                not any(isinstance(v, (Unknown, Alternatives)) for v in found):  # one handle per call site
            return Alternatives(tuple(dict.fromkeys(evaluate(written_args(site)[index]) for site in sites)), True)
        if found or function is None or index < 0:
            return self.unknown(expr, f"call sites pass different values for {what}")
        unknown = self.unknown(expr, f"{param.spelling} comes from a caller in another file: no call site in this "
                                     f"file passes this {what}")  # callers.py looks in the executable's other files
        return FromCaller(unknown.expr, unknown.file, unknown.line, functions=function_keys(function), index=index)

    def each_runs(self, sites: list[ci.Cursor]) -> bool:
        """Whether no two call sites are in different branches of one if/else (only one of those runs)."""
        taken: dict[ci.Cursor, set[bool]] = {}
        for site in sites:
            for condition, branch in self.branches.around(site):
                taken.setdefault(condition, set()).add(branch)
        return all(len(branches) == 1 for branches in taken.values())

    def record_call_sites(self, calls: list[ci.Cursor]) -> None:
        """The handle, name and flag arguments of the calls to the workspace's functions, for
        parameters that files defining them cannot know (callers.py)."""
        for call in calls:
            ref = call.referenced
            if ref is None or ref.kind not in (K.FUNCTION_DECL, K.CXX_METHOD, K.CONSTRUCTOR) or \
                    not self.workspace_code(ref):
                continue
            args = tuple(self.handles.handle_of(a) if is_handle_type(a.type) else
                         self.value(a) if _named_or_flag(a.type) else None for a in written_args(call))
            if any(a is not None for a in args):
                self.result.calls.setdefault(ref.canonical.get_usr(), []).append(args)

    # -- values ---------------------------------------------------------------------------
    def value(self, expr: ci.Cursor, depth: int = 0) -> Value:
        kind = expr.kind
        if depth > 12:
            return self.unknown(expr)
        if kind == K.STRING_LITERAL:
            return unquote(expr.spelling)
        if kind in (K.INTEGER_LITERAL, K.FLOATING_LITERAL, K.CXX_BOOL_LITERAL_EXPR):
            return "".join(t.spelling for t in expr.get_tokens())
        if kind in (K.DECL_REF_EXPR, K.MEMBER_REF_EXPR):
            return self.variable(expr, depth)
        if kind == K.CALL_EXPR:
            return self.call_value(expr, depth)
        if kind == K.CONDITIONAL_OPERATOR:
            *_cond, then, other = list(expr.get_children())
            return alternatives([self.value(then, depth + 1), self.value(other, depth + 1)], False,
                                self.unknown(expr, "one of several values"))
        children = [c for c in expr.get_children() if c.kind not in SKIP]
        if kind in (K.UNEXPOSED_EXPR, K.PAREN_EXPR, K.CXX_FUNCTIONAL_CAST_EXPR, K.CSTYLE_CAST_EXPR,
                    K.CXX_STATIC_CAST_EXPR) and len(children) == 1:
            return self.value(children[0], depth)  # a wrapper: descending it cannot loop
        return self.unknown(expr)

    def variable(self, expr: ci.Cursor, depth: int) -> Value:
        decl = expr.referenced
        key = self.key(decl)
        if key in self.param_vars:
            return self.param_vars[key]
        if key in self.bindings:
            return self.value(self.bindings[key], depth + 1)
        if decl is None:
            return self.unknown(expr)
        if decl.kind == K.PARM_DECL:
            return self.from_call_sites(decl, expr, lambda arg: self.value(arg, depth + 1), decl.spelling)
        if self.key(decl) in self.loops:
            return self.loop_values(self.loops[self.key(decl)], expr, depth)
        if decl.kind in (K.VAR_DECL, K.FIELD_DECL):
            init = [c for c in decl.get_children() if c.kind not in SKIP and not default_constructed(c)]
            if decl.kind == K.FIELD_DECL and not init and (start := initial_value(decl)) is not None:
                init = [start]  # set in a constructor's member initializer list
            if init and decl.type.is_const_qualified():
                return self.value(init[-1], depth + 1)
            assigned = assignments(decl)
            if assigned is not None and (init or assigned):
                assigned = [a for a in assigned if not self_edit(a, decl)]
                found = alternatives([self.value(e, depth + 1) for e in init[-1:] + assigned], False,
                                     self.unknown(expr, "assigned values not all known"))
                return self.edited(found, decl, expr) if decl.kind == K.VAR_DECL else found
        return self.unknown(expr)

    def edited(self, value: Value, decl: ci.Cursor, use: ci.Cursor) -> Value:
        """A string variable's value at `use`, after the edits that cut its start (string_edits.py)."""
        key = self.key(decl)
        if key not in self.edits:
            self.edits[key] = edits(decl) if "string" in decl.type.spelling else []
        for edit in before(self.edits[key], use):
            if edit.cuts is None:
                return self.unknown(use, "string edits not understood")
            value = cut(value, edit.cuts, edit.guarded, self.unknown(use, "a value not known is cut"))
        return value

    def loop_values(self, source: ci.Cursor, expr: ci.Cursor, depth: int) -> Value:
        """A range-for variable over a literal list (or a variable holding one): every element."""
        target = source
        while target.kind in (K.UNEXPOSED_EXPR, K.DECL_REF_EXPR) and target.kind != K.INIT_LIST_EXPR:
            if target.kind == K.DECL_REF_EXPR and target.referenced is not None:
                init = [c for c in target.referenced.get_children() if c.kind not in SKIP]
                target = init[-1] if init else target
                if not init:
                    break
            else:
                children = list(target.get_children())
                if len(children) != 1:
                    break
                target = children[0]
        items = [c for c in target.get_children() if c.kind not in SKIP] if target.kind == K.INIT_LIST_EXPR else []
        return alternatives([self.value(i, depth + 1) for i in items], True,
                            self.unknown(expr, "loop over values not known statically"))

    def call_value(self, expr: ci.Cursor, depth: int) -> Value:
        name, owner = expr.spelling, qualified(expr.referenced.semantic_parent) if expr.referenced else ""
        args = written_args(expr)
        if self.rclcpp is not None and expr.referenced is not None and \
                (found := self.rclcpp.value(expr, owner, name, args, depth)) is not None:
            return found
        if name == "operator+" and len(args) == 2:
            return concat(self.value(args[0], depth + 1), self.value(args[1], depth + 1))
        if owner == "ros::names" and name == "append" and len(args) == 2:
            return concat(self.value(args[0], depth + 1), "/", self.value(args[1], depth + 1))
        if owner in ("ros::names", "") and name in ("resolve", "clean") and args:
            return self.value(args[-1] if name == "resolve" else args[0], depth + 1)
        if owner == "ros::this_node" and name == "getName":  # the full name: resolves as "~" does
            return FullNodeName("~")
        if owner == "ros::this_node" and name == "getNamespace":
            return Namespace()
        if name == "substr" and (count := leading_cut(expr)) is not None and \
                (member := next(expr.get_children())).kind == K.MEMBER_REF_EXPR and \
                (target := next(member.get_children(), None)) is not None:
            return cut(self.value(target, depth + 1), count, False, self.unknown(expr, "a value not known is cut"))
        if owner in (NODE_HANDLE, "ros::param") and name == "param" and len(args) == 2 and is_rvalue(args[1]):
            handle = self.handles.handle_of(next(expr.get_children())) if owner == NODE_HANDLE else ""
            return ParamRef(self.value(args[0], depth + 1), self.value(args[1], depth + 1), handle,
                            self.shown(expr), expr.location.line)
        if owner == NODE_HANDLE and name in ("resolveName", "getNamespace"):
            if name == "getNamespace":
                return Namespace(self.handles.handle_of(next(expr.get_children())))
            return self.value(args[0], depth + 1)
        if name in ("basic_string", "string", "c_str", "str") or (name == "" and len(args) == 1):
            inner = args or [c for c in expr.get_children() if c.kind not in SKIP]
            if len(inner) == 1:
                return self.value(inner[0], depth + 1)
        if self.scope.cls is not None and (returned := override_return(expr, self.kept, self.scope.classes)) is not None:
            return self.value(returned, depth + 1)
        children = [c for c in expr.get_children() if c.kind not in SKIP]
        if len(children) == 1 and not args:
            return self.value(children[0], depth + 1)
        return self.unknown(expr)

    # -- API calls ------------------------------------------------------------------------
    def call(self, call: ci.Cursor) -> None:
        ref = call.referenced
        if ref is None:
            return
        name, args = call.spelling, written_args(call)
        owner = qualified(ref.semantic_parent)
        if self.rclcpp is not None and self.rclcpp.call(call, ref, owner, name, args):
            return
        if ref.kind == K.CONSTRUCTOR and owner in CONSTRUCTED:
            self.constructed(call, owner, args)
        elif ref.kind == K.CONSTRUCTOR and owner in UNDER_NAMESPACE and args:
            namespace = self.value(args[0])
            for port_kind, suffix, port_type in UNDER_NAMESPACE[owner]:
                self.add(port_kind, call, concat(namespace, suffix), port_type, "")
        elif name in ("make_shared", "make_unique") and (made := _made_class(call)) in CONSTRUCTED:
            self.constructed(call, made, args)
        elif owner in ("ros::Rate", "ros::WallRate") and ref.kind == K.CONSTRUCTOR and args:
            hz = self.value(args[0])
            self.add("timer", call, period(hz) if isinstance(hz, str) else self.unknown(call, "rate not constant"),
                     "", "")
        elif owner == "ros" and name == "init" and len(args) >= 3:
            self.result.default_name = self.value(args[2])
            self.result.name_file, self.result.name_line = self.shown(call), call.location.line
            self.result.anonymous = len(args) > 3 and "AnonymousName" in " ".join(
                t.spelling for t in args[3].get_tokens())
        elif owner == LOADER and name == "load" and len(args) >= 2:
            self.result.loads += loaded_nodelets(self, call, args)
        elif (owner, name) in METHODS and args:
            self.method(call, ref, owner, name, args)
        elif owner == NODE_HANDLE and args and name in PARAM_READS | PARAM_WRITES:
            self.param(call, args, self.handles.handle_of(next(call.get_children())), name)
        elif owner == "ros::param" and args and name in PARAM_READS | PARAM_WRITES | {"param"}:
            self.param(call, args, "", name)
        elif (why := _dynamic_params(owner, name, ref)) is not None:
            self.result.params_dynamic = self.result.params_dynamic or \
                f"{self.shown(call)}:{call.location.line}: {why}"
            if creates_plugin(owner, name):
                self.result.plugin_loads.append((self.shown(call), call.location.line))
        elif owner == NODE_HANDLE and name in TIMERS and args:
            self.add("timer", call, self.duration(args[0]), "", self.handles.handle_of(next(call.get_children())))
        elif owner == "ros::service" and name in ("call", "waitForService", "exists") and args:
            type_ = (ros_type(args[1].type) if len(args) > 1 and name == "call" else None) or \
                self.unknown(call, "service type not given")
            self.add("service_client", call, self.value(args[0]), type_, "")

    def method(self, call: ci.Cursor, ref: ci.Cursor, owner: str, name: str, args: list[ci.Cursor]) -> None:
        kind = METHODS[(owner, name)]
        if owner in ("message_filters::Subscriber", IMAGE_FILTER):
            type_ = "sensor_msgs/Image" if owner == IMAGE_FILTER else ros_type(call.referenced.semantic_parent.type) \
                or template_arg_type(call) or self.unknown(call, "message type not resolved")
            self.add(kind, call, self.value(args[1]) if len(args) > 1 else self.unknown(call), type_,
                     self.handles.handle_of(args[0]))
            return
        if owner == NODELET_LAZY:
            self.add(kind, call, self.value(args[1]) if len(args) > 1 else self.unknown(call),
                     self.port_type(call, args, name), self.handles.handle_of(args[0]))
            return
        handle = self.handles.handle_of(next(call.get_children()))
        topic = self.value(args[0])
        if owner == IMAGE_TRANSPORT:
            self.add(kind, call, topic, "sensor_msgs/Image", handle)
            if name.endswith("Camera"):
                self.add(kind, call, camera_info(topic), "sensor_msgs/CameraInfo", handle, info_of=topic)
            return
        queue = self.value(args[1]) if len(args) > 1 and name in ("advertise", "subscribe") else None
        self.add(kind, call, topic, self.port_type(call, args, name), handle,
                 queue=("unbounded" if queue == "0" else queue))

    def constructed(self, call: ci.Cursor, owner: str, args: list[ci.Cursor]) -> None:
        """Library objects whose construction creates ports (tf, actionlib, message_filters...)."""
        has_handle = bool(args) and is_handle_type(args[0].type)
        handle_arg = next((a for a in args if is_handle_type(a.type)), None)  # Server(mutex, nh) has it second
        handle = self.handles.handle_of(handle_arg) if handle_arg is not None else _default_handle(owner)
        type_ = "sensor_msgs/Image" if owner == IMAGE_FILTER else ros_type(call.type) or \
            self.unknown(call, "type not resolved")
        for kind, fixed, index in CONSTRUCTED[owner]:
            if fixed is not None:
                self.add(kind, call, fixed, FIXED_TYPES[fixed], handle)
                continue
            assert index is not None  # a port without a fixed name has its name's argument
            position = index if has_handle else index - 1
            if position >= len(args):
                return  # default-constructed: ports come from a later subscribe()/start()
            self.add(kind, call, self.value(args[position]), type_, handle)

    def members(self, fields: list[ci.Cursor]) -> None:
        """A nodelet's members (of its class and bases) that are library objects with fixed ports
        (a tf listener, say): each instance constructs them, so their ports are the node's."""
        for field in fields:
            owner = qualified(field.type.get_declaration())
            for kind, fixed, _index in CONSTRUCTED.get(owner, []):
                if fixed is not None and field.location.file is not None:
                    loc = field.location
                    self.result.ports.append(Port(kind, fixed, FIXED_TYPES[fixed], self.shown(field), loc.line,
                                                  loc.column, _default_handle(owner)))

    def param(self, call: ci.Cursor, args: list[ci.Cursor], handle: Value, method: str) -> None:
        pname = self.value(args[0])
        if method in PARAM_WRITES:
            value = self.value(args[1]) if len(args) > 1 and method in ("setParam", "set") else "delete"
            self.add("param_write", call, pname, "", handle, value)
            return
        has_default = len(args) > 2 or (method == "param" and len(args) == 2 and is_rvalue(args[1]))
        default = self.value(args[-1]) if has_default else None
        self.add("param_read", call, pname, "", handle, default)
        if len(args) > 1 and isinstance(pname, str) and not (has_default and len(args) == 2):
            target = next((c for c in args[1].walk_preorder() if c.kind in (K.DECL_REF_EXPR, K.MEMBER_REF_EXPR)), None)
            key = self.key(target.referenced) if target is not None else None
            if key is not None and target is not None:
                start = initial_value(target.referenced) if target.referenced.kind == K.FIELD_DECL else None
                fallback = default if default is not None else self.value(start) if start is not None else \
                    self.unknown(call, "parameter without default")
                self.param_vars[key] = ParamRef(pname, fallback, handle, self.shown(call), call.location.line)

    def duration(self, expr: ci.Cursor) -> Value:
        """Seconds of a ros::Duration(x) / ros::Rate(hz) argument."""
        for cursor in expr.walk_preorder():
            if cursor.kind == K.CALL_EXPR and cursor.spelling in ("Duration", "WallDuration", "Rate", "WallRate"):
                args = written_args(cursor)
                if args:
                    value = self.value(args[0])
                    if "Rate" not in cursor.spelling:
                        return value
                    return period(value) if isinstance(value, str) else self.unknown(cursor, "rate not constant")
        return self.unknown(expr, "timer period not resolved")

    def port_type(self, call: ci.Cursor, args: list[ci.Cursor], name: str) -> Value:
        template_arg = template_arg_type(call)
        if template_arg and name != "subscribe":
            return template_arg
        if name in ("subscribe", "advertiseService"):
            for arg in args[1:]:
                for cursor in arg.walk_preorder():
                    target = cursor.referenced if cursor.kind in (K.DECL_REF_EXPR, K.MEMBER_REF_EXPR) else None
                    if target is not None and target.kind in (K.FUNCTION_DECL, K.CXX_METHOD):
                        params = list(target.get_arguments())
                        if params and (found := ros_type(params[0].type)):
                            return found
                    if cursor.kind == K.LAMBDA_EXPR:
                        params = [c for c in cursor.get_children() if c.kind == K.PARM_DECL]
                        if params and (found := ros_type(params[0].type)):
                            return found
                    if "function<" in cursor.type.spelling and (found := type_from_spelling(
                            cursor.type.spelling.split("function<", 1)[1])):
                        return found
        return template_arg or self.unknown(call, "message type not resolved")

    def add(self, kind: str, call: ci.Cursor, name: Value, type_: Value, handle: Value,
            default: Value | None = None, queue: Value | None = None, qos: tuple[tuple[str, str], ...] = (),
            info_of: Value | None = None, *, param: ParamSpec | None = None) -> None:
        if isinstance(name, Alternatives) and name.every:  # a loop makes one port per value
            for option in name.options:
                self.add(kind, call, option, type_, handle, default, queue, qos, param=param)
            return
        if isinstance(handle, Alternatives) and handle.every:  # a handle each call site passes: a port each
            for option in handle.options:
                self.add(kind, call, name, type_, option if isinstance(name, str) else
                         self.unknown(call, "call sites pass different values for NodeHandle"),
                         default, queue, qos, param=param)
            return
        loc, file = call.location, self.shown(call)
        self.port_calls.setdefault(call, []).append(kind)
        if isinstance(name, str) and name.startswith("~") and call.referenced is not None and \
                qualified(call.referenced.semantic_parent) == NODE_HANDLE and not isinstance(name, FullNodeName):
            self.result.diagnostics.append(Diagnostic(
                file, loc.line, "cpp-private-name",
                f"roscpp throws InvalidNameException for '{name}': NodeHandle methods do not accept ~names "
                "(the node dies at start-up); use a NodeHandle(\"~\") instead", "error", loc.column))
        conditions = self.param_conditions(call)
        self.result.ports.append(Port(kind, name, type_, file, loc.line, loc.column, handle, default, qos, queue,
                                      conditions[0] if conditions else None, info_of=info_of,
                                      also=tuple(conditions[1:]), param=param))
        if self.result.graph is not None and (function := self.functions.around(call)) is not None:
            self.result.graph.ports[(file, loc.line, loc.column)] = function

    def param_conditions(self, call: ci.Cursor) -> list[tuple[Value, str | None]]:
        """The parameters the if/else branches around a port's call test, and the values they need
        (innermost first)."""
        found: list[tuple[Value, str | None]] = []
        for variable, holds in required(self.branches.around(call)):
            ref = self.param_vars.get(self.key(variable))
            if ref is None and variable.kind == K.PARM_DECL:  # a flag its callers pass
                ref = self.from_call_sites(variable, call, self.value, variable.spelling)
            if isinstance(ref, (ParamRef, FromCaller)):
                found.append((ref, "true" if holds else "false"))
        return found

    # -- when the AST is incomplete -------------------------------------------------------------
    def token_fallback(self, tu: ci.TranslationUnit) -> None:
        """Read NodeHandle calls from the text of lines where the AST produced no port, and the
        pluginlib loads whose loader's type the AST lost."""
        covered = {p.line for p in self.result.ports if p.file == self.file}
        text = blank_comments(sandbox.read_text(self.source, "source"))
        loaded = {line for file, line in self.result.plugin_loads if file == self.file}
        self.result.plugin_loads += [(self.file, line) for line in plugin_load_lines(text, self.spans)
                                     if line not in loaded]
        if self.ros2:
            ros2_fallback(self, text, covered, tu)
            return
        ports, named = roscpp_fallback(text, self.file, covered, self.spans)
        self.result.ports += ports
        self.result.fallback_lines += [port.line for port in ports]
        self.named_callbacks += named

