"""What the launch, launch_ros (and nav2_common) Python API builds, as values a static reading of
a Python launch file can hold: actions and substitutions become ROS 2 launch actions and substitutions, and the few
standard-library calls launch files use to find files (os.path, pathlib, ament_index_python,
os.environ, open + yaml) are answered from the workspace. Anything else is `Unread`.
"""

from __future__ import annotations

import json
import os
from collections.abc import Callable
from pathlib import Path

import yaml

from archlog import sandbox
from archlog.extract.launch import bounded_yaml
from archlog.extract.launch.model import LaunchError, RefusedRead, SubstitutionError, UnknownArg, Unresolved, read_file
from archlog.extract.launch.ros2_actions import (
    PYTHON,
    XML,
    YAML,
    Action,
    Component,
    Condition,
    DeclareArgument,
    Group,
    Include,
    LoadComponents,
    Node,
    Opaque,
    ParamFile,
    ParamText,
    Process,
    PushNamespace,
    SetConfiguration,
    SetEnvironment,
    SetParameter,
    SetParametersFile,
    SetRemap,
)
from archlog.extract.launch.ros2_api_values import (
    MAX_RANGE,
    CallSite,
    ContextValue,
    Description,
    FileHandle,
    Handler,
    Interpreter,
    PathValue,
    Ref,
    S,
    Source,
    Typed,
    Unread,
    command_words,
    components_of,
    description_source,
    entities,
    include_args,
    listed,
    optional_parts,
    param_value,
    params,
    remap_list,
    to_parts,
    value_kind,
    why,
)
from archlog.extract.launch.ros2_subst import Call, Context, Parts, Rewritten, perform, text


def _declare(c: CallSite) -> object:
    name = c.arg(0, "name")
    if not isinstance(name, str):
        return Unread(f"a launch argument whose name is not known ({why(name)})", c.line)
    choices = c.kwargs.get("choices")
    return DeclareArgument(where=c.where(), conditions=c.conditions(), name=name,
                           default=optional_parts(c.arg(1, "default_value"), c.line),
                           choices=tuple(str(v) for v in choices) if isinstance(choices, (list, tuple)) else None)


def _node(c: CallSite, container: bool = False) -> object:
    exe = c.kwargs.get("executable", c.kwargs.get("node_executable"))
    if exe is None:
        raise LaunchError("Node needs an executable")
    ros_arguments = c.kwargs.get("ros_arguments")
    return Node(where=c.where(), conditions=c.conditions(), pkg=optional_parts(c.kwargs.get("package"), c.line),
                exe=to_parts(exe, c.line), name=optional_parts(c.kwargs.get("name", c.kwargs.get("node_name")), c.line),
                namespace=optional_parts(c.kwargs.get("namespace", c.kwargs.get("node_namespace")), c.line),
                params=params(c.kwargs.get("parameters"), c.line),
                remaps=remap_list(c.kwargs.get("remappings"), c.line),
                arguments=command_words(c.kwargs.get("arguments"), c.line),
                ros_arguments=command_words(ros_arguments, c.line) if ros_arguments is not None else None,
                components=components_of(c.kwargs.get("composable_node_descriptions"), c.where()) if container else ())


def _component(c: CallSite) -> object:
    return Component(where=c.where(), conditions=c.conditions(),
                     pkg=to_parts(c.kwargs.get("package"), c.line), plugin=to_parts(c.kwargs.get("plugin"), c.line),
                     name=optional_parts(c.kwargs.get("name"), c.line),
                     namespace=optional_parts(c.kwargs.get("namespace"), c.line),
                     params=params(c.kwargs.get("parameters"), c.line),
                     remaps=remap_list(c.kwargs.get("remappings"), c.line))


def _load(c: CallSite) -> object:
    target = c.arg(1, "target_container")
    return LoadComponents(where=c.where(), conditions=c.conditions(),
                          target=target if isinstance(target, Node) else to_parts(target, c.line),
                          components=components_of(c.arg(0, "composable_node_descriptions"), c.where()))


def _group(c: CallSite) -> object:
    keep = c.kwargs.get("launch_configurations") or {}
    return Group(where=c.where(), conditions=c.conditions(), actions=tuple(entities(c.arg(0, "actions"), c.where())),
                 scoped=c.kwargs.get("scoped", True) is not False,
                 forwarding=c.kwargs.get("forwarding", True) is not False,
                 keep=tuple((to_parts(k, c.line), to_parts(v, c.line)) for k, v in keep.items())
                 if isinstance(keep, dict) else ())


def _include(c: CallSite) -> object:
    source = description_source(c.arg(0, "launch_description_source"), c.line)
    return Include(where=c.where(), conditions=c.conditions(), target=source.target,
                   args=include_args(c.arg(1, "launch_arguments"), c.line), dialect=source.dialect)


def _opaque_function(c: CallSite) -> object:
    function = c.arg(0, "function")
    extra_args = listed(c.kwargs.get("args"))
    given = c.kwargs.get("kwargs")
    extra_kwargs = {str(k): v for k, v in given.items()} if isinstance(given, dict) else {}
    if isinstance(function, (Unread, Ref)):
        return Opaque(where=c.where(), conditions=c.conditions(), reason=f"OpaqueFunction {_describe(function)}")
    interp, where = c.interp, c.where()

    def run(ctx: Context) -> list[Action]:
        result = interp.call(function, [ContextValue(ctx), *extra_args], dict(extra_kwargs), where.line)
        return entities(result, where)

    return Opaque(where=where, conditions=c.conditions(), reason="OpaqueFunction", run=run)


def _for_each(c: CallSite) -> object:
    """launch's ForEach (launch 3.x): its input performed and split at `;`, each part a YAML mapping
    whose keys are the function's keyword arguments; the entities of every call, in order."""
    values = to_parts(c.arg(0, "input_values"), c.line)
    function = c.arg(1, "function")
    if isinstance(function, (Unread, Ref)):
        return Opaque(where=c.where(), conditions=c.conditions(), reason=f"ForEach {_describe(function)}")
    interp, where = c.interp, c.where()

    def run(ctx: Context) -> list[Action]:
        found: list[Action] = []
        for part in perform(values, ctx).split(";"):
            if not part.strip():
                continue
            try:
                given = bounded_yaml.load(part)
            except yaml.YAMLError as exc:
                raise Unresolved(f"ForEach input {part.strip()!r} is not YAML: {exc}") from None
            if not isinstance(given, dict):
                raise Unresolved(f"ForEach input {part.strip()!r} is not a mapping of the function's arguments")
            found += entities(interp.call(function, [], {str(k): v for k, v in given.items()}, where.line), where)
        return found

    return Opaque(where=where, conditions=c.conditions(), reason="ForEach", run=run)


def _describe(value: object) -> str:
    if isinstance(value, Ref):
        return value.name
    return value.reason if isinstance(value, Unread) else type(value).__name__


def _handler(c: CallSite) -> object:
    for key in ("on_exit", "on_start", "on_completion", "on_stdout", "on_stderr"):
        if key in c.kwargs:
            return Handler(c.kwargs[key])
    return Handler(None)


def _register(c: CallSite) -> object:
    handler = c.arg(0, "event_handler")
    if not isinstance(handler, Handler):
        return Opaque(where=c.where(), conditions=c.conditions(), reason=f"event handler {_describe(handler)}")
    actions = handler.actions
    if actions is not None and not isinstance(actions, (list, tuple, Action)):
        return Opaque(where=c.where(), conditions=c.conditions(), reason="an event handler computed at run time")
    return Group(where=c.where(), conditions=c.conditions(), actions=tuple(entities(actions, c.where())), scoped=False)


def _process(c: CallSite) -> object:
    return Process(where=c.where(), conditions=c.conditions(), cmd=command_words(c.arg(0, "cmd"), c.line))


def _env_action(mode: str) -> Callable[[CallSite], object]:
    def build(c: CallSite) -> object:
        value = None if mode == "unset" else to_parts(c.arg(1, "value"), c.line)
        separator = c.kwargs.get("separator", os.pathsep)
        return SetEnvironment(where=c.where(), conditions=c.conditions(), name=to_parts(c.arg(0, "name"), c.line),
                              value=value, append="" if mode != "append" else
                              ("prepend" if c.kwargs.get("prepend") is True else "append"),
                              separator=to_parts(separator, c.line))
    return build


def _subst(name: str, *keys: str) -> Callable[[CallSite], object]:
    """A substitution class whose arguments (by position or these keywords) are its frontend's."""
    def build(c: CallSite) -> object:
        args = [c.arg(i, key) for i, key in enumerate(keys)]
        while args and args[-1] is None:
            args.pop()
        return S((Call(name, tuple(to_parts(a, c.line) for a in args)),))
    return build


def _equals(name: str) -> Callable[[CallSite], object]:
    def build(c: CallSite) -> object:
        sides = [c.arg(0, "left"), c.arg(1, "right")]
        return S((Call(name, tuple(text("") if v is None else to_parts(v, c.line) for v in sides)),))
    return build


def _path_join(c: CallSite) -> object:
    items = c.arg(0, "substitutions")
    if not isinstance(items, (list, tuple)):
        return S(to_parts(items, c.line))
    return S((Call("path-join", tuple(to_parts(i, c.line) for i in items)),))


def _eval(c: CallSite) -> object:
    modules = c.arg(1, "python_modules")
    args = [to_parts(c.arg(0, "expression"), c.line)]
    if isinstance(modules, (list, tuple)):
        args.append(text(",".join(str(m) for m in modules)))
    return S((Call("eval", tuple(args)),))


def _rewritten(c: CallSite) -> object:
    def pairs(value: object) -> tuple[tuple[str, Parts], ...]:
        return tuple((str(k), to_parts(v, c.line)) for k, v in value.items()) if isinstance(value, dict) else ()

    return S((Rewritten(to_parts(c.arg(0, "source_file"), c.line), optional_parts(c.kwargs.get("root_key"), c.line),
                        pairs(c.arg(1, "param_rewrites")), pairs(c.kwargs.get("value_rewrites")),
                        c.kwargs.get("convert_types") is True),))


def _condition(kind: str) -> Callable[[CallSite], object]:
    def build(c: CallSite) -> object:
        if kind in ("if", "unless"):
            return Condition(kind, to_parts(c.arg(0, "predicate_expression"), c.line))
        name = c.arg(0, "launch_configuration_name")
        return Condition(kind, optional_parts(c.arg(1, "expected_value"), c.line), str(name))
    return build


def _package_dir(name: str) -> Callable[[CallSite], object]:
    """ament_index_python's lookups: a path when the package is here, else a substitution that
    says so when it is used."""
    def build(c: CallSite) -> object:
        pkg = c.arg(0, "package_name")
        found = c.interp.find(pkg) if isinstance(pkg, str) else None
        if found is not None and name == "find-pkg-share":
            return str(found)
        return S((Call(name, (to_parts(pkg, c.line),)),))
    return build


def _action(cls: type, **fields: str) -> Callable[[CallSite], object]:
    """An action whose arguments are all substitutions: each field from the API's argument of that
    name (or position)."""
    def build(c: CallSite) -> object:
        values = {key: to_parts(c.arg(i, arg), c.line) for i, (key, arg) in enumerate(fields.items())}
        return cls(where=c.where(), conditions=c.conditions(), **values)
    return build


def _set_parameter(c: CallSite) -> object:
    return SetParameter(where=c.where(), conditions=c.conditions(), name=to_parts(c.arg(0, "name"), c.line),
                        value=param_value(c.arg(1, "value"), c.line))


def _use_sim_time(c: CallSite) -> object:
    value = c.arg(0, "value")
    return SetParameter(where=c.where(), conditions=c.conditions(), name=text("use_sim_time"),
                        value=value if isinstance(value, bool) else ParamText(to_parts(value, c.line), "bool"))


def _inert(c: CallSite) -> object:
    """Actions with no effect on the architecture (LogInfo, Shutdown, EmitEvent...)."""
    return None


CONSTRUCTORS: dict[str, Callable[[CallSite], object]] = {
    "LaunchDescription": lambda c: Description(listed(c.arg(0, "initial_entities"))),
    "DeclareLaunchArgument": _declare,
    "SetLaunchConfiguration": _action(SetConfiguration, name="name", value="value"),
    "UnsetLaunchConfiguration": lambda c: SetConfiguration(where=c.where(), conditions=c.conditions(),
                                                           name=to_parts(c.arg(0, "name"), c.line), value=None),
    "GroupAction": _group,
    "IncludeLaunchDescription": _include,
    "PythonLaunchDescriptionSource": lambda c: Source(to_parts(c.arg(0, "launch_file_path"), c.line), PYTHON),
    "XMLLaunchDescriptionSource": lambda c: Source(to_parts(c.arg(0, "launch_file_path"), c.line), XML),
    "YAMLLaunchDescriptionSource": lambda c: Source(to_parts(c.arg(0, "launch_file_path"), c.line), YAML),
    "FrontendLaunchDescriptionSource": lambda c: Source(to_parts(c.arg(0, "launch_file_path"), c.line), None),
    "AnyLaunchDescriptionSource": lambda c: Source(to_parts(c.arg(0, "launch_file_path"), c.line), None),
    "OpaqueFunction": _opaque_function, "ForEach": _for_each,
    "TimerAction": lambda c: Group(where=c.where(), conditions=c.conditions(),
                                   actions=tuple(entities(c.arg(1, "actions"), c.where())), scoped=False),
    "RegisterEventHandler": _register,
    "OnProcessExit": _handler, "OnProcessStart": _handler, "OnExecutionComplete": _handler, "OnProcessIO": _handler,
    "OnStateTransition": _handler,
    "OnShutdown": lambda c: Handler(None),
    "ExecuteProcess": _process, "ExecuteLocal": _process,
    "SetEnvironmentVariable": _env_action("set"), "UnsetEnvironmentVariable": _env_action("unset"),
    "AppendEnvironmentVariable": _env_action("append"),
    "LogInfo": _inert, "EmitEvent": _inert, "Shutdown": _inert, "SetROSLogDir": _inert, "LifecycleTransition": _inert,
    "Node": _node, "LifecycleNode": _node,
    "ComposableNodeContainer": lambda c: _node(c, container=True),
    "ComposableNode": _component,
    "LoadComposableNodes": _load,
    "PushRosNamespace": _action(PushNamespace, namespace="namespace"),
    "PushROSNamespace": _action(PushNamespace, namespace="namespace"),
    "SetRemap": _action(SetRemap, src="src", dst="dst"),
    "SetParameter": _set_parameter,
    "SetParametersFromFile": _action(SetParametersFile, path="filename"),
    "SetUseSimTime": _use_sim_time,
    "ParameterFile": lambda c: ParamFile(to_parts(c.arg(0, "param_file"), c.line), c.line,
                                         c.arg(1, "allow_substs", False) is True),
    "ParameterValue": lambda c: Typed(c.arg(0, "value"), value_kind(c.kwargs.get("value_type"))),
    "Parameter": lambda c: Typed(c.arg(1, "value"), value_kind(c.kwargs.get("value_type")),
                                 to_parts(c.arg(0, "name"), c.line)),
    "IfCondition": _condition("if"), "UnlessCondition": _condition("unless"),
    "LaunchConfigurationEquals": _condition("equals"), "LaunchConfigurationNotEquals": _condition("not-equals"),
    "LaunchConfiguration": _subst("var", "variable_name", "default"),
    "EnvironmentVariable": _subst("env", "name", "default_value"),
    "TextSubstitution": lambda c: S(to_parts(c.arg(0, "text"), c.line)),
    "PathJoinSubstitution": _path_join,
    "PythonExpression": _eval,
    "FindPackageShare": _subst("find-pkg-share", "package"),
    "FindPackagePrefix": _subst("find-pkg-prefix", "package"),
    "ThisLaunchFileDir": _subst("dirname"), "ThisLaunchFile": _subst("filename"),
    "AnonName": _subst("anon", "name"),
    "Command": _subst("command", "command"),
    "FindExecutable": _subst("find-exec", "name"),
    "ExecutableInPackage": _subst("exec-in-pkg", "executable", "package"),
    "FileContent": _subst("file-content", "path"),
    "EqualsSubstitution": _equals("equals"), "NotEqualsSubstitution": _equals("not-equals"),
    "NotSubstitution": _subst("not", "value"), "AndSubstitution": _subst("and", "left", "right"),
    "OrSubstitution": _subst("or", "left", "right"),
    "AnySubstitution": lambda c: S((Call("any", tuple(to_parts(a, c.line) for a in c.args)),)),
    "AllSubstitution": lambda c: S((Call("all", tuple(to_parts(a, c.line) for a in c.args)),)),
    "IfElseSubstitution": _subst("if", "condition", "if_value", "else_value"),
    "LaunchConfigAsBool": lambda c: S((Call("as-bool", ((Call("var", (to_parts(c.arg(0, "name"), c.line),)),),)),)),
    "RewrittenYaml": _rewritten,
    "get_package_share_directory": _package_dir("find-pkg-share"),
    "get_package_prefix": _package_dir("find-pkg-prefix"),
}
API_MODULES = ("launch", "launch_ros", "launch_xml", "launch_yaml", "ament_index_python", "nav2_common")


# -- the standard library a launch file uses to find its files ----------------------------
def _plain_path(value: object) -> str | None:
    if isinstance(value, str):
        return value
    return value.path if isinstance(value, PathValue) else None


def _os_path(function: Callable[..., object]) -> Callable[[CallSite], object]:
    def build(c: CallSite) -> object:
        plain = [_plain_path(a) for a in c.args]
        if any(p is None for p in plain):
            return Unread(f"os.path.{function.__name__} of a value not known statically", c.line)
        return function(*plain)
    return build


def probe(test: Callable[[str], bool], path: str, line: int) -> bool | Unread:
    """os.path.exists/isfile/isdir (and Path's): whether a file exists outside the analysed paths
    is the machine's state, not the system's, and is never looked at."""
    if not sandbox.current().inside(path):
        return Unread(f"whether {path} exists is not looked at: it is outside the analysed paths", line)
    return test(path)


def _probe(test: Callable[[str], bool]) -> Callable[[CallSite], object]:
    def build(c: CallSite) -> object:
        path = _plain_path(c.arg(0, "path"))
        if path is None:
            return Unread(f"os.path.{test.__name__} of a value not known statically", c.line)
        return probe(test, path, c.line)
    return build


def _expanduser(c: CallSite) -> object:
    """os.path.expanduser with the HOME the run was given (never the home of archlog's machine)."""
    path = _plain_path(c.arg(0, "path"))
    if path is None or not path.startswith("~"):
        return Unread("os.path.expanduser of a value not known statically", c.line) if path is None else path
    user, sep, rest = path.partition("/")
    if user != "~":
        return Unread(f"the home folder of user {user[1:]}", c.line)
    home = environment(c.interp, "HOME", Unread("the home folder (~): HOME is not given", c.line), c.line)
    return (home.rstrip("/") + sep + rest or "/") if isinstance(home, str) else home


def _getattr(c: CallSite) -> object:
    """getattr(module, 'name'): the attribute of an imported name; of anything else, not read."""
    target, name = c.arg(0, "object"), c.arg(1, "name")
    if isinstance(target, Ref) and isinstance(name, str) and len(c.args) == 2:
        return Ref(f"{target.name}.{name}")
    return Unread("getattr()", c.line)


def _join(c: CallSite) -> object:
    plain = [_plain_path(a) for a in c.args]
    if all(p is not None for p in plain) and plain:
        return os.path.join(*plain)  # type: ignore[arg-type]
    return S((Call("path-join", tuple(to_parts(a, c.line) for a in c.args)),))


def _getenv(c: CallSite) -> object:
    name, default = c.arg(0, "key"), c.arg(1, "default")
    if not isinstance(name, str):
        return Unread("an environment variable whose name is not known", c.line)
    return environment(c.interp, name, default, c.line)


def environment(interp: Interpreter, name: str, default: object, line: int) -> object:
    """An environment variable as os.environ.get(name, default) reads it, from the variables the
    run was given; reading another is reported at `line`."""
    if name not in interp.env:
        if (shell := sandbox.shell_value(name)) is not None:  # --env-from-shell
            return shell
        interp.not_given(sandbox.NotGiven(name, default is not None and not isinstance(default, Unread)), line)
        return default
    value = interp.env[name]
    return Unread(f"environment variable {name} is not known ({value.reason})", line) \
        if isinstance(value, UnknownArg) else value


def _open(c: CallSite) -> object:
    file, mode = c.arg(0, "file"), c.arg(1, "mode", "r")
    path = _plain_path(file)
    if path is None:
        return Unread(f"opening a file whose path is not known ({why(file)})", c.line)
    if not isinstance(mode, str) or any(m in mode for m in "wax+"):
        return Unread(f"{path} opened for writing", c.line)
    return FileHandle(path)


def _chain(c: CallSite) -> object:
    items: list[object] = []
    for arg in c.args:
        if not isinstance(arg, (list, tuple)):
            return Unread("itertools.chain of values not known statically", c.line)
        items.extend(arg)
    return items


def read_text(value: object, line: int, interp: Interpreter) -> str | Unread:
    """The text of a file handle (or of a string), as .read() or yaml.safe_load(f) see it; a file
    the sandbox refuses is reported at `line`."""
    if isinstance(value, str):
        return value
    path = value.path if isinstance(value, (FileHandle, PathValue)) else None
    if path is None:
        return Unread(f"reading {why(value)}", line)
    try:
        return read_file(path, "config")
    except RefusedRead as exc:
        interp.refused_read(exc, line)
        return Unread(str(exc), line)


def _loader(parse: Callable[[str], object]) -> Callable[[CallSite], object]:
    def build(c: CallSite) -> object:
        content = read_text(c.arg(0, "stream"), c.line, c.interp)
        if isinstance(content, Unread):
            return content
        try:
            return parse(content)
        except (yaml.YAMLError, ValueError) as exc:
            return Unread(f"invalid file content: {exc}", c.line)
    return build


def _range(c: CallSite) -> object:
    bounds = [a for a in c.args if isinstance(a, int)]
    if len(bounds) != len(c.args) or not 1 <= len(bounds) <= 3:
        return Unread("range over values not known statically", c.line)
    numbers = range(*bounds)
    return list(numbers) if len(numbers) <= MAX_RANGE else Unread("range too long", c.line)


def perform_in(value: object, context: object, line: int) -> object:
    """A substitution performed in an OpaqueFunction's context (launch's .perform(context))."""
    if not isinstance(context, ContextValue):
        return Unread("perform() outside an OpaqueFunction's context", line)
    try:
        return perform(to_parts(value, line), context.ctx)
    except (Unresolved, SubstitutionError) as exc:
        return Unread(str(exc), line)


FUNCTIONS: dict[str, Callable[[CallSite], object]] = {
    "os.path.join": _join,
    "os.path.dirname": _os_path(os.path.dirname), "os.path.basename": _os_path(os.path.basename),
    "os.path.abspath": _os_path(os.path.abspath), "os.path.realpath": _os_path(os.path.realpath),
    "os.path.normpath": _os_path(os.path.normpath), "os.path.expanduser": _expanduser,
    "os.path.exists": _probe(os.path.exists), "os.path.isfile": _probe(os.path.isfile),
    "os.path.isdir": _probe(os.path.isdir), "os.path.splitext": _os_path(os.path.splitext),
    "os.getenv": _getenv, "os.environ.get": _getenv, "os.environ.copy": lambda c: Ref("os.environ"),
    "builtins.getattr": _getattr,
    "pathlib.Path": lambda c: PathValue(str(Path(*[_plain_path(a) or "" for a in c.args])))
    if all(_plain_path(a) is not None for a in c.args) else Unread("a path not known statically", c.line),
    "yaml.safe_load": _loader(bounded_yaml.load), "yaml.load": _loader(bounded_yaml.load),
    "yaml.full_load": _loader(bounded_yaml.load), "json.load": _loader(json.loads), "json.loads": _loader(json.loads),
    "builtins.open": _open, "builtins.range": _range, "itertools.chain": _chain,
    "launch.utilities.perform_substitutions": lambda c: perform_in(c.arg(1, "subs"), c.arg(0, "context"), c.line),
}
