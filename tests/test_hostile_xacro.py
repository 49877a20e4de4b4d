"""Hostile robot descriptions: xacro files that try to run code, read the environment or files
outside the workspace, or expand without end. Each case is a workspace whose launch file sets one
robot_description per xacro file (`$(find xacro)/xacro $(find pkg)/urdf/NAME`) and spawns it, run
through `archlog check` by the hostile harness; the run must show no execution, no leak, no
traceback and stay in budget, and report each file with the diagnostic expected at its line."""

from __future__ import annotations

import os
import re
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import pytest
import xacro
from support.hostile import CANARY_ENV, Outside, problems, run_check

from archlog.sandbox import NotGiven
from archlog.system.xacro_expand import Expansion, XacroFailure, expand, routed

PACKAGE = """<package format="2"><name>pkg</name><version>0.1.0</version><description>hostile</description>
<maintainer email="dev@example.com">dev</maintainer><license>MIT</license>
<buildtool_depend>catkin</buildtool_depend><exec_depend>xacro</exec_depend></package>
"""
ROBOT = '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n  <link name="base"/>\n{body}\n</robot>\n'
"""A description whose hostile part (`body`) starts on line 3."""

SUBCLASSES = ("[c for c in ().__class__.__base__.__subclasses__() if c.__name__ == 'catch_warnings'][0]()"
              "._module.__builtins__")
"""The builtins reached from a nested code object (a comprehension), where xacro's check of the
code's names does not look."""


def escapes(marker: Path) -> list[str]:
    """Expressions that each try to create `marker` (or reach Python's internals on the way)."""
    m = str(marker)
    return [
        f"(lambda: {SUBCLASSES}['open']('{m}', 'w'))()",
        f"[{SUBCLASSES}['open']('{m}', 'w') for _ in [1]]",
        f"{SUBCLASSES}['__import__']('os').system('touch {m}')",
        "getattr(0, '_' + '_class_' + '_')",
        f"__import__('os').system('touch {m}')",
        f"open('{m}', 'w')",
        f"eval('open(' + chr(39) + '{m}' + chr(39) + ', ' + chr(39) + 'w' + chr(39) + ')')",
        f"exec('open(' + chr(39) + '{m}' + chr(39) + ', ' + chr(39) + 'w' + chr(39) + ')')",
        f"(g for g in [1]).gi_frame.f_globals['_' + '_builtins_' + '_']['open']('{m}', 'w')",
        "(chr(123) + '0._' + '_class_' + '_._' + '_base_' + '_' + chr(125)).format(0)",  # no } inside ${}
        "(chr(123) + '0.real.imag' + chr(125)).format(1)",
        "(chr(123) + '0:' + chr(123) + '1' + chr(125) + chr(125)).format(1, 999999999)",
        "held.format(0)",
        "python.type(0).mro()",
        "python.vars()",
        "xacro.arg.__globals__",
        "xacro.dotify.fromkeys",
        "math.sin.__self__",
        "load_yaml.__func__",
        f"(lambda f: f(f))(lambda f: open('{m}', 'w'))",
    ]


def dollar_evals(marker: Path) -> list[str]:
    """roslaunch `$(eval)` inside a xacro file (xacro runs it with Python's eval; its text ends at
    the first `)`, so these call nothing)."""
    return ["$(eval [].__class__.__mro__[1])", "$(eval [g.gi_frame.f_globals for g in [1]])",
            f"$(eval '{marker}'.__class__)"]


Expected = dict[str, tuple[str, int, str]]
"""Per xacro file: the diagnostic code, the line it is reported at and a text its message holds."""


@dataclass
class Case:
    """A workspace's xacro files (`build` writes any other file itself) and what is reported."""

    name: str
    build: Callable[[Path, Outside], dict[str, str]]
    expected: Callable[[Outside], Expected]


HELD = '<xacro:property name="held" value="{0.__class__.__base__}"/>'
"""A format string a property holds (the expression itself has no double underscore)."""


def _attribute_escapes(ws: Path, outside: Outside) -> dict[str, str]:
    return {f"a{i}.xacro": ROBOT.format(body=f'  {HELD}<link name="${{{e}}}"/>')
            for i, e in enumerate(escapes(outside.marker()))}


def _text_escapes(ws: Path, outside: Outside) -> dict[str, str]:
    probes = [*escapes(outside.marker()), *dollar_evals(outside.marker())]
    return {f"t{i}.xacro": ROBOT.format(body=f"  <e>{e}</e>" if e.startswith("$(") else f"  {HELD}<e>x ${{{e}}}</e>")
            for i, e in enumerate(probes)}


WIDE = 11
"""The escape whose format string takes a width of 999999999 from its arguments: refused by size."""


def _escape_codes(prefix: str, count: int) -> Callable[[Outside], Expected]:
    return lambda outside: {f"{prefix}{i}.xacro": ("budget-exceeded" if i == WIDE else "robot-description", 3, "")
                            for i in range(count)}


ENV_PROBES = {
    "env.xacro": (f'  <link name="$(env {CANARY_ENV})"/>', CANARY_ENV),
    "optenv.xacro": (f"  <link name=\"${{int('$(optenv {CANARY_ENV})')}}\"/>", "invalid literal"),
    "envexpr.xacro": (f"  <link name=\"${{int('$(env {CANARY_ENV})')}}\"/>", CANARY_ENV),
    "arg.xacro": (f"  <xacro:arg name=\"a\" default=\"$(optenv {CANARY_ENV} none)\"/>"
                  "<l n=\"${int(xacro.arg('a'))}\"/>", "invalid literal"),
}


def _env(ws: Path, outside: Outside) -> dict[str, str]:
    return {name: ROBOT.format(body=body) for name, (body, _) in ENV_PROBES.items()}


def _secret_files(ws: Path, outside: Outside) -> dict[str, str]:
    secret = outside.secret_file
    (ws / "pkg" / "urdf" / "link.yaml").symlink_to(secret)
    up = os.path.relpath(secret, ws / "pkg")
    climb = f"$(find pkg)/*/../{os.path.dirname(up)}/*"  # a pattern that climbs out after its first wildcard
    return {"include.xacro": ROBOT.format(body=f'  <xacro:include filename="{secret}"/>'),
            "relative.xacro": ROBOT.format(body=f'  <xacro:include filename="$(find pkg)/{up}"/>'),
            "yaml.xacro": ROBOT.format(body=f"  <link name=\"${{xacro.load_yaml('{secret}')}}\"/>"),
            "linked.xacro": ROBOT.format(body="  <link name=\"${load_yaml('link.yaml')['password']}\"/>"),
            "property.xacro": ROBOT.format(body=f"  <xacro:property name=\"s\" value=\"${{load_yaml('{secret}')}}\"/>"
                                                "<l n=\"${s}\"/>"),
            "listed.xacro": ROBOT.format(body=f'  <xacro:include filename="{secret.parent}/*.yaml"/>'),
            "listedup.xacro": ROBOT.format(body=f'  <xacro:include filename="{climb}"/>')}


LISTED = ("listed.xacro", "listedup.xacro")
"""Include patterns that would list the folder of the secret file: its name is not reported."""


def _secret_expected(outside: Outside) -> Expected:
    named = str(outside.secret_file)
    return {"include.xacro": ("outside-workspace", 3, named), "relative.xacro": ("outside-workspace", 3, "secret.yaml"),
            "yaml.xacro": ("outside-workspace", 3, named), "linked.xacro": ("outside-workspace", 3, "link.yaml"),
            "property.xacro": ("outside-workspace", 3, named), "listed.xacro": ("outside-workspace", 3, "*.yaml"),
            "listedup.xacro": ("outside-workspace", 3, "not listed")}


def _special_files(ws: Path, outside: Outside) -> dict[str, str]:
    urdf = ws / "pkg" / "urdf"
    os.mkfifo(urdf / "fifo.xacro")
    os.mkfifo(urdf / "fifo.yaml")
    (urdf / "zero.xacro").symlink_to("/dev/zero")
    return {"incfifo.xacro": ROBOT.format(body='  <xacro:include filename="fifo.xacro"/>'),
            "yamlfifo.xacro": ROBOT.format(body="  <l n=\"${xacro.load_yaml('fifo.yaml')}\"/>"),
            "devzero.xacro": ROBOT.format(body='  <xacro:include filename="/dev/zero"/>'),
            "linkzero.xacro": ROBOT.format(body='  <xacro:include filename="zero.xacro"/>'),
            "folder.xacro": ROBOT.format(body='  <xacro:include filename="$(find pkg)/urdf"/>')}


SPECIAL_EXPECTED = {"incfifo.xacro": ("not-a-file", 3, "fifo.xacro"), "yamlfifo.xacro": ("not-a-file", 3, "fifo.yaml"),
                    "devzero.xacro": ("outside-workspace", 3, "/dev/zero"),
                    "linkzero.xacro": ("outside-workspace", 3, "zero.xacro"),
                    "folder.xacro": ("not-a-file", 3, "urdf")}


def _doubling(times: int) -> str:
    lines = ['  <xacro:property name="p0" value="xxxxxxxx"/>']
    lines += [f'  <xacro:property name="p{i}" value="${{p{i - 1} + p{i - 1}}}"/>' for i in range(1, times + 1)]
    return "\n".join([*lines, f'  <l n="${{p{times}}}"/>'])


def _fan_out(levels: int) -> str:
    macros = ['  <xacro:macro name="m0" params=""><link name="x"/><link name="y"/></xacro:macro>']
    macros += [f'  <xacro:macro name="m{i}" params="">{f"<xacro:m{i - 1}/>" * 10}</xacro:macro>'
               for i in range(1, levels + 1)]
    return "\n".join([*macros, f"  <xacro:m{levels}/>"])


BOMBS = {  # the body, the line that crosses the budget and what the message says
    "power.xacro": ('  <link name="${10**10**10}"/>', 3, "characters"),
    "tower.xacro": ('  <link name="${((9**64)**64)**64}"/>', 3, "digits"),
    "repeat.xacro": ("  <e>${'a' * 10**9}</e>", 3, "characters"),
    "joined.xacro": ("  <e>${'-'.join(['a' * 100000] * 100000)}</e>", 3, "characters"),
    "replaced.xacro": ("  <e>${('a' * 100000).replace('a', 'a' * 100000)}</e>", 3, "characters"),
    "summed.xacro": ("  <e>${python.sum([[0] * 3000] * 3000, [])}</e>", 3, "characters"),
    "ranged.xacro": ("  <e>${python.list(python.range(10**12))}</e>", 3, "steps"),
    "nested.xacro": ("  <e>${str([[[[0] * 1000] * 1000] * 1000])}</e>", 3, "characters"),
    "doubling.xacro": (_doubling(40), 23, "characters"),  # p20 would take the properties past 20M characters
    "recursion.xacro": ('  <xacro:macro name="boom" params="">\n<xacro:boom/></xacro:macro>\n<xacro:boom/>', 4,
                        "depth"),
    "fanout.xacro": (_fan_out(8), 7, "steps"),  # m4 expands m3 into a parent of thousands of elements
    "selfinclude.xacro": ('  <xacro:include filename="selfinclude.xacro"/>', 3, "depth"),
    "deep.xacro": ("<a>" * 3000 + "</a>" * 3000, 3, "depth"),
}


def _bombs(ws: Path, outside: Outside) -> dict[str, str]:
    urdf = ws / "pkg" / "urdf"
    (urdf / "laughs.yaml").write_text("a: &a [x, x, x, x, x, x, x, x, x, x]\n" + "".join(
        f"{c}: &{c} [{', '.join(['*' + p] * 10)}]\n" for p, c in zip("abcdefgh", "bcdefghi")))
    files = {name: ROBOT.format(body=body) for name, (body, _, _) in BOMBS.items()}
    files["laughs.xacro"] = ROBOT.format(body="  <l n=\"${xacro.load_yaml('laughs.yaml')}\"/>")
    files["entities.xacro"] = '<?xml version="1.0"?>\n<!DOCTYPE r [<!ENTITY a "aaaaaaaaaa">' + "".join(
        f'<!ENTITY {b} "{f"&{a};" * 10}">' for a, b in zip("abcdefghi", "bcdefghij")) + "]>\n<robot>&j;</robot>\n"
    return files


def _bombs_expected(outside: Outside) -> Expected:
    expected = {name: ("budget-exceeded", line, text) for name, (_, line, text) in BOMBS.items()}
    return {**expected, "laughs.xacro": ("budget-exceeded", 3, "characters"),
            "tower.xacro": ("robot-description", 3, "digits"),  # an integer Python could not print
            "entities.xacro": ("robot-description", 2, "entities")}  # expat would stop it only after seconds


def _slow_patterns(ws: Path, outside: Outside) -> dict[str, str]:
    """Inputs on which xacro's own patterns take exponential or quadratic time."""
    params = "p=" + "a" * 60 + "'"
    return {"params.xacro": ROBOT.format(body=f'  <xacro:macro name="m" params="{params}"><l/></xacro:macro>'
                                              '<xacro:m p="1"/>'),
            "dollars.xacro": ROBOT.format(body="  <e>" + "$x" * 300_000 + "</e>\n  <l n='${1/0}'/>")}


CASES = [
    Case("escapes in attributes", _attribute_escapes, _escape_codes("a", len(escapes(Path("m"))))),
    Case("escapes in element text", _text_escapes,
         _escape_codes("t", len(escapes(Path("m"))) + len(dollar_evals(Path("m"))))),
    Case("files outside the workspace", _secret_files, _secret_expected),
    Case("files that are not regular", _special_files, lambda outside: SPECIAL_EXPECTED),
    Case("expansion bombs", _bombs, _bombs_expected),
    Case("slow patterns", _slow_patterns, lambda outside: {"dollars.xacro": ("robot-description", 4, "division")}),
]


def workspace(root: Path, outside: Outside, build: Callable[[Path, Outside], dict[str, str]]) -> Path:
    """A package whose launch file spawns one description per xacro file `build` writes."""
    ws = root / "ws"
    (ws / "pkg" / "urdf").mkdir(parents=True)
    (ws / "pkg" / "launch").mkdir()
    (ws / "pkg" / "package.xml").write_text(PACKAGE)
    files = build(ws, outside)
    for name, text in files.items():
        (ws / "pkg" / "urdf" / name).write_text(text)
    launch = "".join(
        f'  <param name="d{i}" command="$(find xacro)/xacro $(find pkg)/urdf/{name}"/>\n'
        f'  <node pkg="gazebo_ros" type="spawn_model" name="s{i}" args="-urdf -param d{i} -model m{i}"/>\n'
        for i, name in enumerate(sorted(files)))
    (ws / "pkg" / "launch" / "sim.launch").write_text(f"<launch>\n{launch}</launch>\n")
    return ws


def diagnostics(output: str, code: str | None = None) -> dict[str, tuple[int, str, str]]:
    """The text report's diagnostics on xacro files (but env- notes, unless `code` is one of
    them): file name -> (line, code, message)."""
    found = re.findall(r"pkg/urdf/([\w.]+):(\d+): \w+ (.*) ([\w-]+)$", output, re.MULTILINE)
    return {name: (int(line), found_code, message) for name, line, message, found_code in found
            if (found_code == code if code else not found_code.startswith("env-"))}


@pytest.mark.parametrize("case", CASES, ids=lambda case: case.name)
def test_hostile_xacro(case: Case, tmp_path: Path) -> None:
    outside = Outside(tmp_path / "outside")
    ws = workspace(tmp_path, outside, case.build)
    run = run_check(ws, outside, "--launch", "pkg/sim.launch")
    assert problems(run, outside) == []
    reported = diagnostics(run.output)
    expected = case.expected(outside)
    assert {name: (code, line) for name, (line, code, _) in reported.items() if name in expected} == {
        name: (code, line) for name, (code, line, _) in expected.items()}
    for name, (_code, _line, text) in expected.items():
        assert text in reported[name][2], name
        assert name not in LISTED or outside.secret_file.name not in reported[name][2]


@pytest.mark.parametrize("fmt", ["text", "json", "sarif"])
def test_the_environment_is_not_read(fmt: str, tmp_path: Path) -> None:
    """$(env)/$(optenv) see only the sandbox's environment, in every report format: each variable
    read but not given is a note at its line."""
    outside = Outside(tmp_path / "outside")
    ws = workspace(tmp_path, outside, _env)
    run = run_check(ws, outside, "--launch", "pkg/sim.launch", fmt=fmt)
    assert problems(run, outside) == []
    for name, (_, text) in ENV_PROBES.items():
        assert name in run.output
        assert text in run.output
    if fmt == "text":
        reported, notes = diagnostics(run.output), diagnostics(run.output, "env-not-given")
        assert {name: reported[name][:2] for name in ENV_PROBES} == dict.fromkeys(ENV_PROBES, (3, "robot-description"))
        # arg.xacro's $(optenv X none) used its default: a note only with --verbose
        assert {name: notes[name][:2] for name in notes} == dict.fromkeys(set(ENV_PROBES) - {"arg.xacro"},
                                                                          (3, "env-not-given"))
        assert "arg.xacro" not in diagnostics(run.output, "env-default")
        assert "is not given" in reported["env.xacro"][2]


COMMANDS = [
    "sh -c 'touch {marker}'",
    "$(find xacro)/xacro $(find pkg)/urdf/ok.xacro; touch {marker}",
    "$(find xacro)/xacro $(find pkg)/urdf/ok.xacro `touch {marker}` $$(touch {marker})",
    "bash -c &quot;echo &lt;robot/&gt; ; touch {marker}&quot;",
]
"""`<param command=...>` shell payloads, each setting a description that spawn_model reads."""


def test_a_param_command_is_never_run(tmp_path: Path) -> None:
    outside = Outside(tmp_path / "outside")
    ws = workspace(tmp_path, outside, lambda ws, o: {"ok.xacro": ROBOT.format(body="")})
    launch = "".join(
        f'  <param name="c{i}" command="{command.format(marker=outside.marker(f"c{i}"))}"/>\n'
        f'  <node pkg="gazebo_ros" type="spawn_model" name="sc{i}" args="-urdf -param c{i} -model c{i}"/>\n'
        for i, command in enumerate(COMMANDS))
    (ws / "pkg" / "launch" / "sim.launch").write_text(f"<launch>\n{launch}</launch>\n")
    run = run_check(ws, outside, "--launch", "pkg/sim.launch")
    assert problems(run, outside) == []
    assert sorted(map(int, re.findall(r"sim.launch:(\d+): ", run.output))) == [2, 4, 6, 7, 8]  # 7: c2 is not set


def test_the_escape_runs_code_in_plain_xacro(tmp_path: Path) -> None:
    """The probe is real: xacro's own evaluation runs it (here, creating a file in tmp_path)."""
    marker = tmp_path / "ran"
    source = tmp_path / "r.xacro"
    source.write_text(ROBOT.format(body=f'  <link name="${{{escapes(marker)[0]}}}"/>'))
    xacro.process_file(str(source))
    assert marker.exists()
    with pytest.raises(XacroFailure) as failure:
        expand(source, {}, lambda pkg: None)
    marker.unlink()
    assert (failure.value.code, failure.value.place) == ("robot-description", (source, 3))
    assert not marker.exists()


HONEST = """<?xml version="1.0"?>
<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="prefix" default="bot_"/>
  <xacro:property name="cfg" value="${xacro.load_yaml('params.yaml')}"/>
  <xacro:property name="wheel_r" value="${cfg['wheel']['radius']}"/>
  <xacro:property name="name" value="$(arg prefix)base"/>
  <xacro:property name="lst" value="${[1, 2, 3]}"/>
  <xacro:include filename="inc.xacro"/>
  <xacro:include filename="inc.xacro" ns="ns"/>
  <link name="${name}" r="${radians(90)}" c="${cos(pi)}" m="${math.sqrt(2)}" s="${'a' if wheel_r > 0.05 else 'b'}"/>
  <x v="${python.range(3)}" l="${len(lst)}" j="${' '.join(cfg.joints)}" u="${name.upper()}" w="${cfg.wheel.width}"/>
  <x a="${xacro.arg('prefix')}" t="${xacro.tokenize('a,b;c')}" mx="${max(lst)}" sm="${python.sum(lst)}"/>
  <xacro:wheel side="left"><origin xyz="0 0 0"/><ex><a/><b/></ex></xacro:wheel>
  <xacro:ns.wheel side="right" reflect="-1"><origin xyz="1 0 0"/><ex/></xacro:ns.wheel>
  <xacro:chain n="3"/>
  <xacro:unless value="false"><k g="${dict(a=1)}" h="${cfg.wheel.get('radius')}"/></xacro:unless>
  <e>$${literal} ${2**3} $(optenv ARCHLOG_UNSET_VARIABLE dflt) $(eval 1 + 2)</e>
  <xacro:element xacro:name="${'dyn'}" x="1"/>
</robot>
"""
HONEST_INCLUDE = """<robot xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="wheel" params="side reflect:=1 *origin **extra">
    <link name="${side}_wheel"><xacro:insert_block name="origin"/><inertial mass="${reflect * wheel_r * 2}"/>
    <xacro:insert_block name="extra"/></link>
  </xacro:macro>
  <xacro:macro name="chain" params="n">
    <link name="l${n}"/><xacro:if value="${n > 0}"><xacro:chain n="${n-1}"/></xacro:if>
  </xacro:macro>
</robot>
"""


def test_honest_xacro_expands_as_xacro_does_and_xacro_is_restored(tmp_path: Path) -> None:
    (tmp_path / "params.yaml").write_text("wheel: {radius: 0.1, width: !millimeters 40}\njoints: [a, b, c]\n")
    (tmp_path / "inc.xacro").write_text(HONEST_INCLUDE)
    source = tmp_path / "r.xacro"
    source.write_text(HONEST)
    before = {name: getattr(xacro, name) for name in ("eval_text", "safe_eval", "parse", "eval_all",
                                                      "_global_symbols", "re_macro_arg", "all_includes")}
    expanded = expand(source, {}, lambda pkg: tmp_path if pkg == "pkg" else None)
    assert {name: getattr(xacro, name) for name in before} == before
    assert expanded.text == xacro.process_file(str(source)).toxml()
    assert "l0" in expanded.text and 'mass="-0.2"' in expanded.text and "${literal} 8 dflt 3" in expanded.text
    assert set(expanded.files) == {source, tmp_path / "inc.xacro", tmp_path / "params.yaml"}
    assert expanded.unseen == [(NotGiven("ARCHLOG_UNSET_VARIABLE", defaulted=True), (source, 17))]


def test_xacro_is_restored_after_a_failure(tmp_path: Path) -> None:
    source = tmp_path / "r.xacro"
    source.write_text(ROBOT.format(body='  <xacro:macro name="m" params=""><l n="${10**10**10}"/></xacro:macro>'
                                        '<xacro:m/>'))
    state = ("eval_text", "safe_eval", "parse", "eval_all", "replace_node", "_global_symbols", "re_macro_arg",
             "all_includes", "glob", "substitution_args_context", "filestack", "macrostack")
    before = {name: getattr(xacro, name) for name in state}
    with pytest.raises(XacroFailure) as failure:
        expand(source, {"a": "1"}, lambda pkg: None)
    assert (failure.value.code, failure.value.place) == ("budget-exceeded", (source, 3))
    assert {name: getattr(xacro, name) for name in state} == before
    with routed(Expansion(lambda pkg: None)):
        assert xacro.eval_text is not before["eval_text"]
    assert xacro.eval_text is before["eval_text"]
