"""Diagnostics: problems with the input (not findings about the system), always with file:line.

Every code is registered in `CODES` (docs/diagnostics.md is generated from it); creating a
diagnostic with an unregistered code is a programming error and raises `ValueError`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

SEVERITIES = ("error", "warning", "note")
VERBOSE_ONLY = frozenset({"env-default"})  # codes a report lists only with --verbose: nothing to act on


@dataclass(frozen=True)
class Code:
    """A diagnostic code: its usual severity, what it means, and what to do about it."""

    severity: str
    meaning: str
    help: str
    group: str


def _codes(group: str, table: dict[str, tuple[str, str, str]]) -> dict[str, Code]:
    return {code: Code(severity, meaning, help_, group) for code, (severity, meaning, help_) in table.items()}


CODES: dict[str, Code] = {
    **_codes("Workspace", {
        "package-xml": ("warning", "A package.xml is invalid; the package name is taken from its text if possible.",
                        "Fix the manifest (catkin_pkg's message says what is wrong)."),
        "duplicate-package": ("warning", "Two folders hold a package of the same name; the first is used.",
                              "Remove or ignore (CATKIN_IGNORE) the copy."),
        "plugin-xml": ("warning", "A plugin description file named in package.xml cannot be read.",
                       "Check the export's plugin= path."),
        "cmake-subdirectory": ("warning", "An add_subdirectory() names a folder whose CMakeLists.txt is being read (its "
                               "own folder or a parent); CMake refuses it, and it is skipped.",
                               "Remove the add_subdirectory()."),
        "setup-cfg": ("warning", "setup.cfg does not parse; its entry points are unknown.", "Fix its syntax."),
        "setup-py": ("warning", "setup.py does not parse; its entry points are unknown.",
                     "Fix its syntax (it is read, never run)."),
    }),
    **_codes("Launch files", {
        "launch-xml": ("error", "A launch file is not well-formed XML, or its root is not <launch>.",
                       "Fix the XML at the line given."),
        "launch-yaml": ("error", "A YAML launch file does not parse or has the wrong shape.",
                        "Fix the YAML at the line given."),
        "launch-python": ("error", "A Python launch file does not parse or lacks generate_launch_description().",
                          "Fix the file; it is read with ast, never run."),
        "launch-include": ("error", "An included launch file is not found.", "Check the include's file path."),
        "launch-include-cycle": ("error", "A launch file includes itself, directly or through others (roslaunch "
                                 "would recurse until it fails); the include is skipped.", "Break the cycle."),
        "launch-invalid": ("error", "An element is invalid as roslaunch or launch_ros would reject it.",
                           "Fix the element as the message says."),
        "launch-tag": ("warning", "An unrecognized tag is ignored.", "Check the tag's spelling."),
        "launch-attr": ("warning", "An unknown attribute is ignored.", "Check the attribute's spelling."),
        "launch-subst": ("error", "A substitution is invalid ($(...) syntax, an undefined arg).",
                         "Fix the substitution."),
        "launch-unresolved": ("warning", "A value depends on the machine (an unset variable, a package that is not "
                              "here) and is not known statically; the element is skipped or its value unknown.",
                              "Pass the value with --arg, --env, or add the package to the analysed paths."),
        "launch-arg-unknown": ("note", "A launch argument has no value statically.", "Pass it with --arg NAME:=VALUE."),
        "launch-condition": ("note", "An if/unless condition cannot be decided statically; the element is kept "
                             "as conditional (a condition on one unknown argument is tried with the values it is "
                             "written with, so that elements whose conditions exclude each other are known not to "
                             "run together).", "Pass the args it depends on with --arg."),
        "launch-process": ("note", "An ExecuteProcess that launch_ros does not start as a ROS node is left out.",
                           "Nothing, unless it is a node: then launch it with Node."),
        "launch-unknown": ("warning", "Part of a Python launch file is not read statically (a while loop, a loop "
                           "over an unknown value).", "Write the launch description without run-time control flow, "
                           "or model what it starts."),
        "param-file": ("warning", "A parameter file is not found or cannot be read.", "Check the file path."),
        "node-name": ("note", "A node's name or namespace is not known statically; a default is used.",
                      "Name the node in the launch file."),
        "controller-type": ("warning", "A controller spawner starts a controller whose type is not set.",
                            "Load the controller's parameters (NAME/type) in this configuration."),
    }),
    **_codes("Sources", {
        "cpp-missing": ("error", "A source file listed in CMakeLists.txt does not exist.", "Fix the CMake target."),
        "cpp-parse": ("error", "libclang cannot parse a C++ file at all.", "Check the file."),
        "cpp-compile": ("warning", "A C++ file does not compile here (often a missing header); its ROS calls are "
                        "also read from the tokens.", "Install the package that provides the header, or add its "
                        "include folder to the analysed paths."),
        "cpp-crash": ("error", "The C++ parser crashed on an executable; its ROS calls are not recovered.",
                      "Report it; meanwhile describe the node with --model."),
        "cpp-stand-in": ("note", "archlog's stand-in ROS headers lack an API a line uses; it is read from the "
                         "tokens.", "Nothing; report the API if its ports are missing."),
        "cpp-ros1-stand-in": ("note", "A C++ file includes ROS 1 library headers that are not installed (ros/ros.h "
                              "...); it is read with archlog's stand-in headers, which declare the same API.",
                              "Nothing; install the ROS 1 headers to read it with the real ones."),
        "cpp-private-name": ("error", "A NodeHandle method is given a ~name: roscpp throws at start-up.",
                             "Use a NodeHandle(\"~\") and a relative name."),
        "cpp-several-nodes": ("note", "A C++ file creates several nodes; they are read as one.",
                              "Split the nodes, or model them."),
        "msg-definition": ("warning", "A message definition cannot be turned into a C++ header.",
                           "Fix the .msg/.srv/.action file."),
        "msg-headers": ("note", "The workspace's message headers cannot be generated (gencpp missing or failed); "
                        "C++ ports using them get unknown types.", "Install Debian's python3-gencpp."),
        "python-syntax": ("error", "A Python source parses neither as Python 3 nor after Python 2 repair.",
                          "Fix the syntax."),
        "python2": ("note", "Python 2 syntax was repaired line by line to read the file's ROS calls.",
                    "Port the file to Python 3."),
        "python-several-nodes": ("note", "One piece of Python code (an rclpy Node subclass, or the code outside them) "
                                 "creates several nodes; they are read as one.",
                                 "Split the nodes, or model them."),
        "python-behavior": ("note", "A file has more paths than the behavior walk's budget; some publish "
                            "triggers are unknown.", "Nothing; the triggers not found are unknown."),
        "python-nesting": ("error", "A Python source is nested deeper than Python's parser (or archlog's walk over "
                           "its tree) allows; its ROS calls are not recovered.", "Flatten the expression at the "
                           "line given."),
        "cpp-macro": ("error", "A macro of a C++ file or its workspace headers expands to more than a million "
                      "tokens (doubling macros, or nested calls of a macro that copies its argument); the file is "
                      "not parsed.", "Remove the macro, or describe the node with --model."),
        "cpp-walk": ("error", "The walk over a C++ file's syntax tree ran out of memory or depth; its ROS calls "
                     "are not recovered.", "Split the file, or describe the node with --model."),
        "port-name-unknown": ("note", "A port's name could not be known statically (it comes from a caller in "
                              "another file, a parameter without a default, or an expression); the port connects to "
                              "nothing, the rules assume it might be the counterpart of any name of its type (of any "
                              "name that fits the parts that are known, as in `ns + \"/scan\"`), and its node counts "
                              "as partially recovered.",
                              "Give the value (a launch argument or parameter), or describe the node with --model."),
        "name-too-long": ("note", "A topic or service name has too many segments or characters to be compared for "
                          "near misses; it is not.", "Nothing, unless the name is a mistake."),
    }),
    **_codes("Models and configured ports", {
        "no-model": ("warning", "A node has neither source nor model: its ports are unknown.",
                     "Describe it in a YAML model passed with --model (see archlog/models/)."),
        "nodelet-unknown": ("warning", "An executable loads a nodelet into its own process (nodelet::Loader::load) "
                            "whose ports are unknown: the plugin has no source or model, or its name is not known "
                            "statically.", "Add the plugin's package to the analysed paths, or describe the node "
                            "with --model."),
        "model-drift": ("note", "A node's source and archlog's shipped model of it disagree on port names (the one "
                        "with fewer resolved ports is not used).",
                        "Check which is right; fix the source or pass a corrected model with --model."),
        "model-yaml": ("error", "A model file is not valid YAML.", "Fix the YAML."),
        "model-schema": ("error", "A model does not follow the model schema.",
                         "Fix it as the message says (archlog/models/model.schema.json)."),
        "robot-description": ("warning", "A robot description (URDF/xacro) cannot be read or expanded, or an "
                              "include of it names a package not here (the include is left out, the rest read). "
                              "The spawner of such a description is partial: its gazebo plugins may be more.",
                              "Fix the description, or add the folder of the package it includes to the analysed "
                              "paths; xacro expressions are evaluated by archlog's restricted evaluator."),
        "tf-args": ("warning", "A node that broadcasts the transform its command line gives (static_transform_publisher) "
                    "has arguments that are not `x y z yaw pitch roll frame child` nor `x y z qx qy qz qw frame child`; "
                    "the transform it broadcasts is unknown, so no transform can be reported missing.",
                    "Give the six or seven numbers, then the parent and the child frame."),
        "plugin-no-model": ("note", "A robot description loads a gazebo plugin that archlog has no model of "
                            "(archlog/models/plugins/), or a node's parameters make it load a pluginlib class "
                            "that no model file's `classes:` describes; the ports it creates are unknown.",
                            "Add the plugin to archlog/models/plugins/gazebo.yaml, or the class to a model "
                            "file's `classes:` (passed with --model)."),
        "xacro-legacy": ("note", "A xacro file calls a macro without the xacro: prefix (<kobuki/>), which older "
                         "xacro accepted with a deprecation warning; archlog expands it as a macro call.",
                         "Write <xacro:NAME/>."),
        "rviz-config": ("warning", "An rviz configuration cannot be read; its displays' topics are unknown.",
                        "Check the -d path."),
        "param-library": ("warning", "A generate_parameter_library definition (YAML) that a node links cannot be "
                          "read or does not parse; the node's parameters are not all known, so AL403 does not judge "
                          "it.", "Fix the file's YAML, or its path in generate_parameter_library()."),
        "ports-file": ("warning", "A YAML file that a node's parameter names, and whose entries are ports of "
                       "the node (yocs_cmd_vel_mux's yaml_cfg_file), cannot be read, or lacks an entry or has one "
                       "without a name; those ports are unknown.",
                       "Check the parameter's value (an absolute path, usually $(find PKG)/...) and the file's "
                       "entries against the node's documentation."),
    }),
    **_codes("Trust boundary (see docs/security.md)", {
        "outside-workspace": ("error", "A file outside the analysed paths and package roots was asked for; it is "
                              "not read, and only its path is shown.", "Add its folder to the analysed paths if "
                              "it belongs to the system."),
        "not-a-file": ("error", "A path that should be a file is a directory, device, FIFO or missing; it is not "
                       "read.", "Point the reference at a regular file."),
        "env-not-given": ("note", "An environment variable was read that was not given (--env, [env] in "
                          "archlog.toml, or the allow-list); it reads as unset. Only its name is shown.",
                          "Pass it with --env NAME=VALUE if the system depends on it."),
        "env-from-shell": ("note", "Environment variables the input asks for were read from the shell archlog runs "
                           "in (--env-from-shell, for local checks); only their names are shown. A name that looks "
                           "like a secret's is never read.", "In CI, pass each with --env NAME=VALUE instead, so "
                           "the result does not depend on the machine."),
        "env-default": ("note", "An environment variable that was not given was read with a default written next "
                        "to it ($(optenv X default), EnvironmentVariable's default_value, os.environ.get's), "
                        "which is used. Listed only with --verbose.",
                        "Pass it with --env NAME=VALUE if the system runs with another value."),
        "too-large": ("error", "A file is over the size cap for its kind; it is not read.",
                      "Raise the cap (docs/security.md) if the file is honest."),
        "budget-exceeded": ("warning", "An expansion (a robot description, an expression) went past a limit of "
                            "the budget; what it had read before stays.", "Raise the limit named in [budget] of "
                            "archlog.toml (docs/security.md) if the input is honest."),
    }),
    **_codes("Generated tests", {
        "testgen-message": ("warning", "A message type of an input or output has no definition, or a line of its "
                            ".msg file does not parse; its topic (or field) gets no strategy.",
                            "Index the package that defines it (pass its folder) or fix the .msg line."),
    }),
    **_codes("Reports", {
        "unused-suppression": ("warning", "An inline suppression, or a `[[suppress]]` entry of archlog.toml, "
                               "matches no finding.", "Remove it, or correct its rule, node or topic."),
        "stale-baseline": ("warning", "A baseline entry matches no finding of the run (the finding was fixed, "
                           "or its names changed).", "Remove the entry, or write the baseline again."),
    }),
}


@dataclass(frozen=True, order=True)
class Diagnostic:
    """A problem archlog met while reading the input, e.g. a launch file that does not parse."""

    file: str
    line: int
    code: str
    message: str
    severity: str = "warning"
    column: int = 0

    def __post_init__(self) -> None:
        if self.code not in CODES:
            raise ValueError(f"unregistered diagnostic code {self.code!r}: add it to archlog.diagnostics.CODES")

    def __str__(self) -> str:
        return f"{self.file}:{self.line}: {self.severity}: {self.message} [{self.code}]"


def _usual(code: str) -> str:
    return CODES[code].severity if code in CODES else "warning"  # an unknown code raises in Diagnostic


@dataclass
class DiagnosticSink:
    """Collects diagnostics from every stage; order of arrival is kept and duplicates dropped."""

    items: list[Diagnostic] = field(default_factory=list)

    def add(self, file: str, line: int, code: str, message: str, severity: str | None = None,
            column: int = 0) -> None:
        """Record a diagnostic; without `severity`, the code's registered one."""
        diag = Diagnostic(str(file), line, code, message, severity or _usual(code), column)
        if diag not in self.items:
            self.items.append(diag)

    def extend(self, diagnostics: list[Diagnostic]) -> None:
        """Record diagnostics found elsewhere (a worker process, a cached result)."""
        for diag in diagnostics:
            self.add(diag.file, diag.line, diag.code, diag.message, diag.severity, diag.column)
