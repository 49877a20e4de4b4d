"""Hostile workspaces that read the environment (issue 15): launch files of every dialect read the
CI job's secret variable in every way they can. archlog reads only the variables it is given
(--env, [env] in archlog.toml) and the ROS allow-list: the secret never reaches a report, each read
is an `env-not-given` diagnostic at file:line naming the variable, and a given value is used.

All cases share one workspace (one launch file each, all launched together as one system), checked
in every format without the variable and once with `--env ARCHLOG_CANARY_SECRET=given`.
"""

from __future__ import annotations

import json
import textwrap
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import pytest
from support.hostile import CANARY_ENV, Outside, Run, problems, run_check

PACKAGE_XML = """<?xml version="1.0"?>
<package format="2"><name>demo</name><version>0.0.1</version><description>demo</description>
<maintainer email="demo@example.com">demo</maintainer><license>MIT</license></package>
"""
PY_HEADER = """import os
from launch import LaunchDescription
from launch.substitutions import EnvironmentVariable
from launch_ros.actions import Node

"""
DISTRO = "hostiledistro"


@dataclass(frozen=True)
class Case:
    """A launch file (under demo/launch/) whose node's package is read from the environment at
    `line`; the `no-model` diagnostic shows the package (and the case's name as the executable),
    so a value read is visible."""

    file: str
    text: str
    line: int


def ros1(tag: str) -> Callable[[str], Case]:
    return lambda name: Case(f"{name}.launch", f"<launch>\n  {tag.replace('NAME', name)}\n</launch>\n", 2)


def ros2_xml(name: str) -> Case:
    return Case(f"{name}.launch.xml", f'<launch>\n  <node pkg="pkg_$(env {CANARY_ENV})" exec="{name}" name="{name}"/>\n'
                "</launch>\n", 2)


def ros2_yaml(name: str) -> Case:
    return Case(f"{name}.launch.yaml", f"launch:\n- node: {{pkg: 'pkg_$(env {CANARY_ENV} fallback)', exec: {name}, "
                f"name: {name}}}\n", 2)


def python(prelude: str, package: str) -> Callable[[str], Case]:
    """A Python launch file: `prelude` lines in generate_launch_description, then a node whose
    package is `package` (an expression). The read is on the line marked `# READ`, else the node's."""
    def build(name: str) -> Case:
        lines = [*prelude.splitlines(), f"return LaunchDescription([Node(package={package}, executable='{name}', "
                                        f"name='{name}')])"]
        text = PY_HEADER + "def generate_launch_description():\n" + "".join(f"    {line}\n" for line in lines)
        numbered = text.splitlines()
        read = next((i for i, line in enumerate(numbered, 1) if "# READ" in line), len(numbered))
        return Case(f"{name}.launch.py", text, read)
    return build


def py_opaque_function(name: str) -> Case:
    """EnvironmentVariable performed in an OpaqueFunction: reported at the OpaqueFunction action."""
    text = (PY_HEADER + "from launch.actions import OpaqueFunction\n\n\ndef setup(context):\n"
            f"    package = 'pkg_' + EnvironmentVariable('{CANARY_ENV}', default_value='x').perform(context)\n"
            f"    return [Node(package=package, executable='{name}', name='{name}')]\n\n\n"
            "def generate_launch_description():\n    return LaunchDescription([OpaqueFunction(function=setup)])\n")
    return Case(f"{name}.launch.py", text, len(text.splitlines()))


def ros1_include(name: str) -> Case:
    text = (f'<launch>\n  <include file="$(dirname)/{name}_inner.xml">\n'
            f'    <arg name="pkg" value="pkg_$(env {CANARY_ENV})"/>\n  </include>\n</launch>\n')
    return Case(f"{name}.launch", text, 2)


CASES: dict[str, Callable[[str], Case]] = {
    "ros1_env": ros1(f'<node pkg="pkg_$(env {CANARY_ENV})" type="NAME" name="NAME"/>'),
    "ros1_optenv": ros1(f'<node pkg="pkg_$(optenv {CANARY_ENV} fallback)" type="NAME" name="NAME"/>'),
    "ros1_eval_env": ros1(f'<node pkg="$(eval \'pkg_\' + env(\'{CANARY_ENV}\'))" type="NAME" name="NAME"/>'),
    "ros1_eval_optenv": ros1(f'<node pkg="$(eval \'pkg_\' + optenv(\'{CANARY_ENV}\', \'x\'))" type="NAME" '
                             'name="NAME"/>'),
    "ros1_arg_default": lambda name: Case(
        f"{name}.launch", f'<launch>\n  <arg name="p" default="pkg_$(env {CANARY_ENV})"/>\n'
        f'  <node pkg="$(arg p)" type="{name}" name="{name}"/>\n</launch>\n', 2),
    "ros1_include_arg": ros1_include,
    "ros2_xml_env": ros2_xml,
    "ros2_yaml_env": ros2_yaml,
    "py_environment_variable": python("", f"['pkg_', EnvironmentVariable('{CANARY_ENV}', default_value='x')]"),
    "py_opaque_function": py_opaque_function,
    "py_environ_index": python(f"value = os.environ['{CANARY_ENV}']  # READ", "'pkg_' + value"),
    "py_environ_get": python(f"value = os.environ.get('{CANARY_ENV}', 'x')  # READ", "'pkg_' + value"),
    "py_getenv": python(f"value = os.getenv('{CANARY_ENV}')  # READ", "'pkg_' + str(value)"),
    "py_dict_environ": python(f"env = dict(os.environ)\nvalue = env['{CANARY_ENV}']  # READ", "'pkg_' + value"),
    "py_environ_copy": python(f"env = os.environ.copy()\nvalue = env.get('{CANARY_ENV}')  # READ", "'pkg_' + value"),
    "py_getattr_environ": python(f"env = getattr(os, 'environ')\nvalue = env['{CANARY_ENV}']  # READ",
                                 "'pkg_' + value"),
    "py_from_os_import": python(f"from os import environ, getenv\nvalue = getenv('{CANARY_ENV}') and "
                                f"environ['{CANARY_ENV}']  # READ", "'pkg_' + str(value)"),
    "py_name_built": python("name = 'ARCHLOG_CANARY' + '_SECRET'\nvalue = os.environ[name]  # READ", "'pkg_' + value"),
}

DEFAULTED = {"ros1_optenv", "ros1_eval_optenv", "ros2_yaml_env", "py_environment_variable", "py_opaque_function",
             "py_environ_get"}  # the variable is read with a default written next to it


def build_workspace(root: Path) -> dict[str, Case]:
    launch = root / "src" / "demo" / "launch"
    launch.mkdir(parents=True)
    (root / "src" / "demo" / "package.xml").write_text(PACKAGE_XML)
    (launch / "ros1_include_arg_inner.xml").write_text(
        '<launch>\n  <arg name="pkg"/>\n  <node pkg="$(arg pkg)" type="ros1_include_arg" name="ros1_include_arg"/>\n'
        '</launch>\n')
    (launch / "allowed.launch").write_text('<launch>\n  <node pkg="pkg_$(env ROS_DISTRO)" type="t" name="allowed"/>\n'
                                           "</launch>\n")
    cases = {name: build(name) for name, build in CASES.items()}
    for case in cases.values():
        (launch / case.file).write_text(case.text)
    return cases


@dataclass
class Runs:
    outside: Outside
    cases: dict[str, Case]
    hidden: dict[str, Run]  # format -> run without the variable
    given: Run  # json, with --env ARCHLOG_CANARY_SECRET=given
    plain: Run  # json, without --verbose


@pytest.fixture(scope="module")
def runs(tmp_path_factory: pytest.TempPathFactory) -> Runs:
    root = tmp_path_factory.mktemp("hostile_env")
    workspace, outside = root / "ws", Outside(root / "outside")
    cases = build_workspace(workspace)
    launches = [f"--launch=src/demo/launch/{file}" for file in [*(c.file for c in cases.values()), "allowed.launch"]]
    with pytest.MonkeyPatch.context() as patch:
        patch.setenv("ROS_DISTRO", DISTRO)
        hidden = {fmt: run_check(workspace, outside, *launches, "--verbose", fmt=fmt) for fmt in ("text", "json", "sarif")}
        plain = run_check(workspace, outside, *launches, fmt="json")
        given = run_check(workspace, outside, *launches, f"--env={CANARY_ENV}=given", fmt="json")
    return Runs(outside, cases, hidden, given, plain)


def diagnostics(run: Run) -> list[dict]:
    return json.loads(run.output[run.output.index("{"):])["diagnostics"]


@pytest.mark.parametrize("fmt", ["text", "json", "sarif"])
def test_the_secret_reaches_no_report(runs: Runs, fmt: str) -> None:
    assert problems(runs.hidden[fmt], runs.outside) == []
    assert "env-not-given" in runs.hidden[fmt].output and "ros1_env.launch" in runs.hidden[fmt].output


@pytest.mark.parametrize("name", list(CASES))
def test_each_read_is_reported_at_its_line_naming_the_variable(runs: Runs, name: str) -> None:
    """With --verbose every read is listed: env-default where the input's own default was used,
    env-not-given where there was none; without --verbose only the latter."""
    case = runs.cases[name]
    code = "env-default" if name in DEFAULTED else "env-not-given"
    found = [d for d in diagnostics(runs.hidden["json"]) if d["code"].startswith("env-")
             and d["file"] == f"src/demo/launch/{case.file}"]
    assert [(d["line"], d["code"]) for d in found] == [(case.line, code)], found
    assert CANARY_ENV in found[0]["message"] and f"--env {CANARY_ENV}=" in found[0]["message"]
    plain = [d["code"] for d in diagnostics(runs.plain) if d["file"] == f"src/demo/launch/{case.file}"
             and d["code"].startswith("env-")]
    assert plain == ([] if name in DEFAULTED else ["env-not-given"])


@pytest.mark.parametrize("name", list(CASES))
def test_a_given_value_is_used(runs: Runs, name: str) -> None:
    assert problems(runs.given, runs.outside) == []
    shown = [d["message"] for d in diagnostics(runs.given) if d["code"] == "no-model"]
    assert any(f"for pkg_given/{name}:" in message for message in shown), shown
    assert not [d for d in diagnostics(runs.given) if d["code"] == "env-not-given"
                and d["file"] == f"src/demo/launch/{runs.cases[name].file}"]


def test_the_ros_release_is_read_from_the_machine(runs: Runs) -> None:
    messages = [d["message"] for d in diagnostics(runs.hidden["json"]) if "allowed.launch" in d["file"]]
    assert any(f"pkg_{DISTRO}/t" in m for m in messages) and not any("ROS_DISTRO" in m for m in messages), messages


# -- configuration: [env] and [budget] ------------------------------------------------------
def small_workspace(root: Path, config: str | None = None) -> Path:
    """A package with one ROS 1 launch file whose node's package is read from the canary variable."""
    launch = root / "src" / "demo" / "launch"
    launch.mkdir(parents=True)
    (root / "src" / "demo" / "package.xml").write_text(PACKAGE_XML)
    (launch / "main.launch").write_text(CASES["ros1_env"]("main").text)
    if config is not None:
        (root / "archlog.toml").write_text(textwrap.dedent(config))
    return root


def test_env_from_the_configuration_and_the_command_line(tmp_path: Path) -> None:
    outside = Outside(tmp_path / "outside")
    workspace = small_workspace(tmp_path / "ws", f'[env]\n{CANARY_ENV} = "fromtoml"\n')
    from_file = run_check(workspace, outside, "--launch=src/demo/launch/main.launch")
    overridden = run_check(workspace, outside, "--launch=src/demo/launch/main.launch", f"--env={CANARY_ENV}=fromcli")
    assert problems(from_file, outside) == [] and problems(overridden, outside) == []
    assert "pkg_fromtoml/main" in from_file.output and "env-not-given" not in from_file.output
    assert "pkg_fromcli/main" in overridden.output and "fromtoml" not in overridden.output


BAD_CONFIGS = {
    "[env]\nROBOT = 1\n": "[env] ROBOT must be a string",
    'env = "ROBOT=r2"\n': "[env] must be a table",
    '[env]\n"A=B" = "x"\n': "[env] 'A=B' is not an environment variable name",
    "[budget]\nelements = 0\n": "[budget] elements must be a positive whole number, not 0",
    "[budget]\nsteps = true\n": "[budget] steps must be a positive whole number, not True",
    "[budget]\ndepth = 1.5\n": "[budget] depth must be a positive whole number, not 1.5",
    "[budget]\nbytes = 10\n": "[budget] bytes is not a limit (known: elements, nodes, characters, steps, alternatives, depth)",
    'budget = "big"\n': "[budget] must be a table",
}


@pytest.mark.parametrize("config", list(BAD_CONFIGS))
def test_a_bad_env_or_budget_table_is_a_configuration_error(tmp_path: Path, config: str) -> None:
    outside = Outside(tmp_path / "outside")
    run = run_check(small_workspace(tmp_path / "ws", config), outside, "--launch=src/demo/launch/main.launch")
    assert problems(run, outside) == []
    assert run.returncode == 2 and f"archlog.toml: {BAD_CONFIGS[config]}" in run.output, run.output


def test_budget_limits_are_read_over_the_defaults(tmp_path: Path) -> None:
    from archlog.config import load_config

    (tmp_path / "archlog.toml").write_text('[budget]\nelements = 500000\ndepth = 8\n[env]\nROBOT = "r2"\n')
    config = load_config(tmp_path / "archlog.toml", None)
    assert (config.limits, config.env) == ({"elements": 500000, "depth": 8}, {"ROBOT": "r2"})


@pytest.mark.parametrize("option", ["--env=ROBOT", "--env==r2"])
def test_a_bad_env_option_is_a_usage_error(tmp_path: Path, option: str) -> None:
    outside = Outside(tmp_path / "outside")
    run = run_check(small_workspace(tmp_path / "ws"), outside, option)
    assert problems(run, outside) == [] and run.returncode == 2 and "--env" in run.output, run.output


# -- rule files: no #script, no #include ------------------------------------------------------
def script(outside: Outside, language: str) -> str:
    if language == "python":
        return f"#script (python)\nopen({str(outside.marker())!r}, 'w').write('ran')\n#end.\n"
    return f'#script (lua)\nio.open("{outside.marker()}", "w"):write("ran")\n#end.\n'


RULE_FILES = {
    "python_script": lambda outside: "seen(N) :- node(N, _, _, _).\n" + script(outside, "python"),
    "lua_script": lambda outside: "% a library of derived relations\n" + script(outside, "lua"),
    "include_secret": lambda outside: f'#include "{outside.secret_file}".\n',
}


@pytest.mark.parametrize("how", ["config", "option"])
@pytest.mark.parametrize("kind", list(RULE_FILES))
def test_a_rule_file_with_a_script_or_include_is_refused(tmp_path: Path, kind: str, how: str) -> None:
    outside = Outside(tmp_path / "outside")
    workspace = small_workspace(tmp_path / "ws", 'rules = ["rules/"]\n' if how == "config" else None)
    text = RULE_FILES[kind](outside)
    (workspace / "rules").mkdir()
    (workspace / "rules" / "extra.lp").write_text(text)
    options = [] if how == "config" else ["--rules=rules/extra.lp"]
    run = run_check(workspace, outside, "--launch=src/demo/launch/main.launch", *options)
    assert problems(run, outside) == [] and run.returncode == 2, run.output
    directive = "#include" if kind == "include_secret" else "#script"
    line = text.splitlines().index(next(t for t in text.splitlines() if t.startswith(directive))) + 1
    assert f"extra.lp:{line}:1: rule files may not contain {directive}" in run.output, run.output


def test_a_workspace_configuration_cannot_raise_budgets_or_reach_outside(tmp_path: Path) -> None:
    """archlog.toml found in the workspace is pull-request content: its [budget] only lowers limits,
    and its rule files stay under its folder; the same file given with --config is trusted."""
    from archlog.budget import LIMITS
    from archlog.config import load_config, workspace_config
    from archlog.errors import ConfigError

    (tmp_path / "archlog.toml").write_text('[budget]\nelements = 999999999\ndepth = 8\n')
    found = workspace_config(load_config(tmp_path / "archlog.toml", None))
    assert found.limits == {"elements": LIMITS["elements"], "depth": 8}

    outside = Outside(tmp_path / "outside")
    (outside.root / "rules").mkdir()
    (outside.root / "rules" / "r.lp").write_text("% nothing\n")
    workspace = small_workspace(tmp_path / "ws", f'rules = ["{outside.root / "rules"}"]\n')
    with pytest.raises(ConfigError, match="outside"):
        workspace_config(load_config(workspace / "archlog.toml", None))
    run = run_check(workspace, outside, "--launch=src/demo/launch/main.launch")
    assert problems(run, outside) == [] and run.returncode == 2 and "is outside" in run.output, run.output
    trusted = run_check(workspace, outside, "--launch=src/demo/launch/main.launch",
                        f"--config={workspace / 'archlog.toml'}")
    assert trusted.returncode in (0, 1), trusted.output
