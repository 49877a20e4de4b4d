"""Configuration: `archlog.toml`, or `[tool.archlog]` in pyproject.toml, with profiles.

    rules = ["team_rules/"]           # extra rule files or folders
    select = ["AL1", "topics"]        # rule ids (or id prefixes) and tags to run; default: all
    ignore = ["AL104", "launch-process"]  # ids, prefixes, tags, diagnostic codes or code prefixes
                                      # ("launch-") to leave out (docs/diagnostics.md lists codes)
    near-miss-threshold = 0.5
    [severity]
    AL401 = "error"                   # a rule's or a diagnostic code's severity
    [[suppress]]                      # accepted findings: rule, node, topic, service globs
    rule = "AL102"
    topic = "/debug/*"
    reason = "debug topics are read by hand"
    [profiles.ci]                     # --profile ci: overrides the keys above
    ignore = ["AL104"]
    [env]                             # environment variables launch files may read ($(env), os.environ);
    ROBOT_NAME = "r2"                 # --env NAME=VALUE adds or overrides; no other variable of the
                                      # machine is read but ROS_DISTRO, ROS_VERSION, ROS_PYTHON_VERSION
    [budget]                          # expansion limits per unit of input (archlog.budget.LIMITS)
    elements = 500000                 # keys: elements, nodes, characters, steps, alternatives, depth
    operators = ["rviz2", "teleop2"]  # operator tools outside the launch files that feed topics
                                      # (archlog/models/operators/; docs/models.md)
    [systems.nav]                     # `archlog check --system nav`: a named system configuration
    paths = ["src"]                   # relative to this file; PATH arguments are added
    launch = ["nav_bringup/launch/nav.launch"]
    args = {use_sim = "false"}        # launch arguments (--arg wins)
    models = ["models/lidar.yaml"]
    operators = ["rviz"]

Built-in profiles: `ci` (precision: only high- and medium-precision rules, threshold 0.4) and
`audit` (recall: every rule, threshold 0.6); a configuration file may redefine them.
"""

from __future__ import annotations

import difflib
import re
import tomllib
from dataclasses import dataclass, field, replace
from pathlib import Path

from archlog import sandbox
from archlog.budget import LIMITS
from archlog.diagnostics import CODES, SEVERITIES, VERBOSE_ONLY, Diagnostic
from archlog.errors import ConfigError
from archlog.rules.ruleset import Rule

BUILTIN_PROFILES = {
    "ci": {"precision": ["high", "medium"], "near-miss-threshold": 0.4},
    "audit": {"near-miss-threshold": 0.6},
}
KEYS = {"rules", "select", "ignore", "severity", "near-miss-threshold", "precision", "profiles", "suppress", "env",
        "budget", "operators", "systems"}
SYSTEM_KEYS = {"paths", "launch", "args", "models", "operators"}
OPERATORS = Path(__file__).resolve().parent / "models" / "operators"


@dataclass
class System:
    """A named system configuration of archlog.toml: what `--system NAME` puts on the command line."""

    paths: list[Path] = field(default_factory=list)
    launch: list[str] = field(default_factory=list)
    args: dict[str, str] = field(default_factory=dict)
    models: list[Path] = field(default_factory=list)


@dataclass
class Config:
    rule_paths: list[Path] = field(default_factory=list)
    select: list[str] = field(default_factory=list)
    ignore: list[str] = field(default_factory=list)
    severity: dict[str, str] = field(default_factory=dict)
    precision: list[str] = field(default_factory=list)
    near_miss_threshold: float = 0.5
    suppress: list[dict] = field(default_factory=list)
    env: dict[str, str] = field(default_factory=dict)
    limits: dict[str, int] = field(default_factory=dict)
    operators: list[Path] = field(default_factory=list)  # the model files of the operator tools named
    systems: dict[str, System] = field(default_factory=dict)
    source: Path | None = None

    def applies(self, rule: Rule) -> bool:
        """Whether a rule runs under this configuration (select, ignore, precision)."""
        keys = {rule.id, rule.name, *rule.tags}
        def matches(patterns: list[str]) -> bool:
            return any(p in keys or rule.id.startswith(p) for p in patterns)
        select = [p for p in self.select if not is_code(p)]
        return (not select or matches(select)) and not matches(self.ignore) and \
            (not self.precision or rule.precision in self.precision)

    def diagnostics(self, items: list[Diagnostic], verbose: bool = False) -> list[Diagnostic]:
        """The diagnostics shown: `select` and `ignore` take diagnostic codes or code prefixes
        (`launch-`) as they take rule ids, and `[severity]` overrides a code's severity; the
        VERBOSE_ONLY codes only with `verbose` or when selected by their full code."""
        select = [p for p in self.select if is_code(p)]
        def matches(code: str, patterns: list[str]) -> bool:
            return any(code == p or (p.endswith("-") and code.startswith(p)) for p in patterns)
        return [replace(d, severity=self.severity.get(d.code, d.severity)) for d in items
                if (not select or matches(d.code, select)) and not matches(d.code, self.ignore)
                and (verbose or d.code not in VERBOSE_ONLY or d.code in select)]

    def adjust(self, rules: list[Rule]) -> list[Rule]:
        """The rules that apply, with severity overrides."""
        return [replace(r, severity=self.severity.get(r.id, r.severity)) for r in rules if self.applies(r)]


def is_code(pattern: str) -> bool:
    """Whether a select/ignore pattern names a diagnostic code (or a prefix of codes), not a rule."""
    return any(code == pattern or (pattern.endswith("-") and code.startswith(pattern)) for code in CODES)


def find_config(paths: list[Path]) -> Path | None:
    """archlog.toml, or a pyproject.toml with [tool.archlog], in the first path or above it, or in
    the current folder."""
    starts = [p.resolve() for p in paths[:1]] + [Path.cwd()]
    for start in starts:
        for folder in [start, *start.parents] if start.is_dir() else start.parents:
            if (folder / "archlog.toml").is_file():
                return folder / "archlog.toml"
            pyproject = folder / "pyproject.toml"
            if pyproject.is_file() and "tool" in (data := _read(pyproject)) and "archlog" in data["tool"]:
                return pyproject
    return None


def load_config(path: Path | None, profile: str | None) -> Config:
    data: dict = {}
    if path is not None:
        raw = _read(path)
        data = raw.get("tool", {}).get("archlog", {}) if path.name == "pyproject.toml" else raw
        unknown = set(data) - KEYS
        if unknown:
            raise ConfigError(f"{path}: unknown key(s) {', '.join(sorted(unknown))}")
    profiles = {**BUILTIN_PROFILES, **data.get("profiles", {})}
    if profile is not None:
        if profile not in profiles:
            raise ConfigError(f"unknown profile '{profile}' (known: {', '.join(sorted(profiles))})")
        data = {**data, **profiles[profile]}
    base = path.parent if path is not None else Path.cwd()
    config = Config(
        rule_paths=[(base / p) for p in data.get("rules", [])],
        select=list(data.get("select", [])), ignore=list(data.get("ignore", [])),
        severity=dict(data.get("severity", {})), precision=list(data.get("precision", [])),
        near_miss_threshold=float(data.get("near-miss-threshold", 0.5)), suppress=_suppress(data.get("suppress", []), path),
        env=_env(data.get("env", {}), path), limits=_budget(data.get("budget", {}), path),
        operators=_operators(data.get("operators", []), path, "operators"),
        systems={name: _system(name, table, base, path) for name, table in _table(data, "systems", path).items()},
        source=path,
    )
    for rule_id, level in config.severity.items():
        if level not in SEVERITIES:
            raise ConfigError(f"{path}: severity of {rule_id} must be one of {', '.join(SEVERITIES)}")
    for rule_path in config.rule_paths:
        if not rule_path.exists():
            raise ConfigError(f"{path}: rule path {rule_path} does not exist")
    return config


SUPPRESS_KEYS = ("rule", "node", "topic", "service", "reason")


def _suppress(entries: object, path: Path | None) -> list[dict]:
    """[[suppress]] entries, each with the `line` of its header: only known keys, string values, and
    at least one of rule, node, topic or service (an entry of none would hide every finding)."""
    if not isinstance(entries, list) or not all(isinstance(e, dict) for e in entries):
        raise ConfigError(f"{path}: suppress must be a list of [[suppress]] tables")
    text = sandbox.read_text(path, "config").splitlines() if path is not None and entries else []
    headers = [n for n, line in enumerate(text, 1) if re.match(r"\s*\[\[\s*(tool\.archlog\.)?suppress\s*\]\]", line)]
    result = []
    for index, entry in enumerate(entries):
        start = headers[index] if index < len(headers) else 0
        end = headers[index + 1] if index + 1 < len(headers) else len(text) + 1

        def line_of(key: str, start: int = start, end: int = end) -> int:
            return next((n for n in range(start, end) if re.match(rf"\s*{re.escape(key)}\s*=", text[n - 1])), start)

        for key, value in entry.items():
            if key not in SUPPRESS_KEYS:
                near = difflib.get_close_matches(key, SUPPRESS_KEYS, n=1)
                raise ConfigError(f"{path}:{line_of(key)}: [[suppress]] has an unknown key '{key}' (known: "
                                  f"{', '.join(SUPPRESS_KEYS)}" + (f"; did you mean '{near[0]}'?)" if near else ")"))
            if not isinstance(value, str):
                raise ConfigError(f"{path}:{line_of(key)}: [[suppress]] {key} must be a string (a glob)")
        if not set(entry) - {"reason"}:
            raise ConfigError(f"{path}:{start}: [[suppress]] names no rule, node, topic or service, so it would hide "
                              "every finding")
        result.append({**entry, "line": start})
    return result


def _env(table: object, path: Path | None) -> dict[str, str]:
    """[env]: variable names to string values (a message never shows a value)."""
    if not isinstance(table, dict):
        raise ConfigError(f"{path}: [env] must be a table of NAME = \"value\"")
    for name, value in table.items():
        if not name or "=" in name or "\0" in name:
            raise ConfigError(f"{path}: [env] {name!r} is not an environment variable name")
        if not isinstance(value, str):
            raise ConfigError(f"{path}: [env] {name} must be a string")
    return dict(table)


def _table(data: dict, key: str, path: Path | None) -> dict:
    table = data.get(key, {})
    if not isinstance(table, dict):
        raise ConfigError(f"{path}: [{key}] must be a table")
    return table


def _strings(value: object, path: Path | None, where: str) -> list[str]:
    if not isinstance(value, list) or not all(isinstance(v, str) and v for v in value):
        raise ConfigError(f"{path}: {where} must be a list of strings such as [\"a\", \"b\"]")
    return list(value)


def operator_tools() -> list[str]:
    """The operator tools archlog ships a model of (archlog/models/operators/NAME.yaml)."""
    return sorted(p.stem for p in OPERATORS.glob("*.yaml"))


def _operators(value: object, path: Path | None, where: str) -> list[Path]:
    """`operators = ["rviz2", ...]`: the shipped models of these operator tools."""
    names = _strings(value, path, where)
    for name in names:
        if name not in operator_tools():
            raise ConfigError(f"{path}: {where}: unknown operator tool '{name}' "
                              f"(known: {', '.join(operator_tools())}; or write a model, docs/models.md)")
    return [OPERATORS / f"{name}.yaml" for name in names]


def _system(name: str, table: object, base: Path, path: Path | None) -> System:
    """[systems.NAME]: paths and models relative to the configuration's folder."""
    where = f"[systems.{name}]"
    if not isinstance(table, dict):
        raise ConfigError(f"{path}: {where} must be a table")
    unknown = set(table) - SYSTEM_KEYS
    if unknown:
        raise ConfigError(f"{path}: {where}: unknown key(s) {', '.join(sorted(unknown))} "
                          f"(known: {', '.join(sorted(SYSTEM_KEYS))})")
    args = table.get("args", {})
    if not isinstance(args, dict) or not all(isinstance(v, str) for v in args.values()):
        raise ConfigError(f"{path}: {where} args must be a table of NAME = \"value\"")
    paths = [base / p for p in _strings(table.get("paths", []), path, f"{where} paths")]
    models = [base / p for p in _strings(table.get("models", []), path, f"{where} models")]
    for given in [*paths, *models]:
        if not given.exists():
            raise ConfigError(f"{path}: {where}: {given} does not exist")
    return System(paths, _strings(table.get("launch", []), path, f"{where} launch"), dict(args),
                  models + _operators(table.get("operators", []), path, f"{where} operators"))


def _budget(table: object, path: Path | None) -> dict[str, int]:
    """[budget]: limits (keys of archlog.budget.LIMITS) as positive integers."""
    if not isinstance(table, dict):
        raise ConfigError(f"{path}: [budget] must be a table of limit = number")
    for kind, value in table.items():
        if kind not in LIMITS:
            raise ConfigError(f"{path}: [budget] {kind} is not a limit (known: {', '.join(LIMITS)})")
        if isinstance(value, bool) or not isinstance(value, int) or value <= 0:
            raise ConfigError(f"{path}: [budget] {kind} must be a positive whole number, not {value!r}")
    return dict(table)


def workspace_config(config: Config) -> Config:
    """A configuration found next to the analysed paths is workspace content (it comes with the pull
    request): its rule files must lie under its own folder, and its [budget] may lower limits but
    not raise them. Give --config to use a trusted file as it is."""
    assert config.source is not None
    home = config.source.parent.resolve()
    for rule_path in config.rule_paths:
        if not rule_path.resolve().is_relative_to(home):
            raise ConfigError(f"{config.source}: rule path {rule_path} is outside {home}; a configuration found "
                              "in the workspace may only use rule files under its own folder (or pass --config)")
    for name, system in config.systems.items():
        for given in [*system.paths, *system.models]:
            if not given.resolve().is_relative_to(home) and given.parent != OPERATORS:
                raise ConfigError(f"{config.source}: [systems.{name}] names {given}, outside {home}; a configuration "
                                  "found in the workspace may only name files under its own folder (or pass --config)")
    return replace(config, limits={kind: min(value, LIMITS[kind]) for kind, value in config.limits.items()})


def _read(path: Path) -> dict:
    try:
        return tomllib.loads(sandbox.read_text(path, "config"))
    except (sandbox.Refused, tomllib.TOMLDecodeError, RecursionError) as exc:
        raise ConfigError(f"{path}: {exc}") from None
