"""The `archlog` command line: check, facts, query, repl, graph, behavior, test-rules, rule, observe, diff."""

from __future__ import annotations

import json
import os
import sys
from contextlib import nullcontext
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

import click

from archlog import __version__, cli_choices, sandbox
from archlog.diagnostics import SEVERITIES
from archlog.errors import ConfigError
from archlog.rules.ruleset import RuleError

if TYPE_CHECKING:  # the heavy parts (clingo, libclang, numpy, rich) load in the commands that use them

    from archlog.analysis import Analysis
    from archlog.config import Config
    from archlog.reports.paths import Rebase
    from archlog.rules.engine import Finding
    from archlog.rules.ruleset import RuleSet

FAIL_ON = (*SEVERITIES, "never")


def _arg_pairs(values: tuple[str, ...]) -> dict[str, str]:
    pairs = {}
    for value in values:
        if ":=" not in value:
            raise click.BadParameter(f"expected NAME:=VALUE, got {value!r}", param_hint="--arg")
        name, val = value.split(":=", 1)
        pairs[name] = val
    return pairs


def _env_pairs(values: tuple[str, ...]) -> dict[str, str]:
    pairs = {}
    for value in values:
        name, sep, val = value.partition("=")
        if not sep or not name:  # the message never shows a value
            raise click.BadParameter(f"expected NAME=VALUE, got {value!r}" if not sep else "NAME= is empty",
                                     param_hint="--env")
        pairs[name] = val
    return pairs


def _remember_shell_flag(ctx: click.Context, _param: click.Parameter, value: bool) -> bool:
    """--env-from-shell, kept for _inputs (the commands do not take it as an argument)."""
    ctx.meta["env_from_shell"] = value
    return value


def _system_options(func):
    options = [
        click.argument("paths", nargs=-1, type=click.Path(path_type=Path)),
        click.option("--launch", "launches", multiple=True, metavar="FILE_OR_PKG/FILE",
                     help="Launch file of the configuration (repeatable; together they form one system)."),
        click.option("--arg", "args", multiple=True, metavar="NAME:=VALUE", help="Launch argument (repeatable)."),
        click.option("--env", "env", multiple=True, metavar="NAME=VALUE",
                     help="Environment variable launch files may read (repeatable); no other is read from this "
                          "machine but ROS_DISTRO, ROS_VERSION and ROS_PYTHON_VERSION."),
        click.option("--env-from-shell", is_flag=True, expose_value=False, callback=_remember_shell_flag,
                     help="Also read, from this shell, each environment variable the launch files ask for and "
                          "--env does not give (a local check; never set by a configuration file; names that "
                          "look like secrets are not read). CI should pass --env."),
        click.option("--model", "models", multiple=True, type=click.Path(path_type=Path),
                     help="YAML node models for nodes without source, or external producers/consumers."),
        click.option("--rules", "rule_paths", multiple=True, type=click.Path(exists=True, path_type=Path),
                     help="Extra rule file or folder of .lp files (repeatable)."),
        click.option("--config", "config_path", type=click.Path(exists=True, dir_okay=False, path_type=Path),
                     help="archlog.toml or pyproject.toml (default: found next to the first PATH or above)."),
        click.option("--profile", help="Configuration profile, e.g. ci (precision) or audit (recall)."),
        click.option("--near-miss-threshold", type=click.FloatRange(0, 5),
                     help="Normalised name distance below which two names are a near miss [default: 0.5]."),
    ]
    func = cli_choices.options(func)
    for option in reversed(options):
        func = option(func)
    return func


@dataclass
class Inputs:
    """What one run analyses: the configuration and rules, the system's inputs and environment."""

    config: Config
    ruleset: RuleSet
    paths: list[Path]
    launches: list[str]
    args: dict[str, str]
    models: list[Path]
    env: dict[str, str]
    env_from_shell: bool = False


def _inputs(paths, launches, args, models, rule_paths, config_path, profile, threshold, env) -> Inputs:
    """Configuration, rules (checked before the slow part) and the system's inputs. The environment
    is [env] of the configuration with --env over it."""
    from archlog.config import find_config, load_config, workspace_config
    from archlog.rules.ruleset import load_rules

    config = load_config(config_path or find_config(list(paths)), profile)
    if config_path is None and config.source is not None:
        config = workspace_config(config)
    if threshold is not None:
        config.near_miss_threshold = threshold
    ruleset = load_rules([*config.rule_paths, *rule_paths])
    choices = cli_choices.given()
    config = cli_choices.select(config, choices, ruleset.rules)
    paths, launches, args, models = cli_choices.inputs(config, choices, list(paths), list(launches),
                                                       _arg_pairs(args), list(models))
    shell = bool(click.get_current_context().meta.get("env_from_shell"))
    return Inputs(config, ruleset, paths, launches, args, models, {**config.env, **_env_pairs(env)}, shell)


def _analyse(given: Inputs, quiet: bool = False) -> Analysis:
    """The analysis of the inputs, with a progress bar on a terminal."""
    from rich.console import Console
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, SpinnerColumn, TextColumn, TimeElapsedColumn

    from archlog.analysis import analyse

    config = given.config
    stderr = Console(stderr=True)
    if quiet or not stderr.is_terminal:
        return analyse(given.paths, given.launches, given.args, given.models, config.near_miss_threshold,
                       env=given.env, limits=config.limits, env_from_shell=given.env_from_shell)
    with Progress(SpinnerColumn(), TextColumn("reading nodes"), BarColumn(), MofNCompleteColumn(),
                  TimeElapsedColumn(), console=stderr, transient=True) as bar:
        task = bar.add_task("nodes", total=None)

        def advance(done: int, total: int) -> None:
            bar.update(task, completed=done, total=total if total > 0 else None)

        return analyse(given.paths, given.launches, given.args, given.models, config.near_miss_threshold,
                       advance, env=given.env, limits=config.limits, env_from_shell=given.env_from_shell)


def _load(paths, launches, args, models, rule_paths, config_path, profile, threshold, env,
          quiet: bool = False) -> tuple[Analysis, RuleSet, Config]:
    """The configuration, the rules and the analysis of one run."""
    given = _inputs(paths, launches, args, models, rule_paths, config_path, profile, threshold, env)
    return _analyse(given, quiet), given.ruleset, given.config


def _in_repository(analysis: Analysis, ruleset: RuleSet, config: Config, rebase: Rebase
                   ) -> tuple[list[Finding], dict]:
    """The findings, each at a location in the analysed repository (a shipped model or a file
    outside it only as a related location), and the labels of the locations they left."""
    from archlog.queries.session import Session
    from archlog.reports.relocate import relocate, shipped

    return relocate(Session(analysis.store, ruleset, config).findings(), analysis.store,
                    lambda file: shipped(file) or os.path.isabs(rebase(file)))


@click.group(context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, prog_name="archlog")
def main() -> None:
    """Find architecture misconfigurations in ROS systems before the robot runs."""


@main.command()
@_system_options
@click.option("--format", "fmt",
              type=click.Choice(["text", "concise", "json", "sarif", "codequality", "github", "junit"]),
              default="text", show_default=True,
              help="concise: one `path:line:col: ID message` line per finding and a summary; codequality: GitLab's "
                   "Code Quality; github: workflow command annotations; junit: one failing test case per finding.")
@click.option("--source-root", "source_root_dir", type=click.Path(exists=True, file_okay=False, path_type=Path),
              help="Report paths relative to this folder [default: the git work tree holding the first PATH, "
                   "else the current folder].")
@click.option("--output", type=click.Path(path_type=Path), help="Write the report here instead of stdout.")
@click.option("--fail-on", type=click.Choice(FAIL_ON), default="error", show_default=True,
              help="Exit 1 when a finding of this severity or worse exists (suppressed ones do not count).")
@click.option("--baseline", type=click.Path(exists=True, dir_okay=False, path_type=Path),
              help="Report only findings that are not in this baseline (matched by fingerprint).")
@click.option("--write-baseline", type=click.Path(dir_okay=False, path_type=Path),
              help="Record the current findings as the baseline.")
@click.option("--new-only", is_flag=True, help="Report only the findings the change introduces relative to --base "
              "(matched by fingerprint, so moved lines do not count as new).")
@click.option("--base", "base_ref", default="HEAD", show_default=True, metavar="REF",
              help="With --new-only: the git revision the change is compared with.")
@click.option("--fail-on-incomplete", is_flag=True,
              help="Also exit 1 when a node is only partially recovered or opaque (no model or source), or a "
                   "part of the launch configuration was not read (an include skipped, an action not interpreted).")
@click.option("--quiet", "-q", is_flag=True, help="Text: one line per finding and the summary.")
@click.option("--verbose", "-v", is_flag=True, help="Also list the notes that need no action (an environment "
              "variable not given whose default, written next to it, was used).")
@click.option("--fix", "fix", is_flag=True, help="Apply the safe fixes (remaps in launch files) and report what remains.")
@click.option("--unsafe-fixes", is_flag=True, help="With --fix or --diff: the fixes that may change the meaning too.")
@click.option("--diff", "show_diff", is_flag=True,
              help="Print the fixes as a unified diff instead of applying them (exit 1 when there is one).")
def check(paths, launches, args, models, rule_paths, config_path, profile, near_miss_threshold, env, fmt,
          source_root_dir, output, fail_on, baseline, write_baseline, new_only, base_ref, fail_on_incomplete, quiet, verbose,
          fix, unsafe_fixes, show_diff) -> None:
    """Check a ROS system configuration and report findings."""
    from rich.console import Console

    from archlog.reports.annotations import to_github, to_junit
    from archlog.reports.codequality import to_codequality
    from archlog.reports.json_report import to_json
    from archlog.reports.paths import Rebase, source_root
    from archlog.reports.report import Report, coverage, holes
    from archlog.reports.sarif import to_sarif
    from archlog.reports.suppress import apply_suppressions, read_baseline, stale_baseline
    from archlog.reports.suppress import write_baseline as write_baseline_file
    from archlog.reports.text import print_concise, print_text

    given = _inputs(paths, launches, args, models, rule_paths, config_path, profile, near_miss_threshold, env)
    ruleset, config = given.ruleset, given.config
    analysis = _analyse(given, quiet or fmt != "text" and output is None)
    root = analysis.workspace.roots[0]
    rebase = Rebase(analysis.workspace.roots, source_root(root, source_root_dir))
    findings, labels = _in_repository(analysis, ruleset, config, rebase)
    files = {str(row[1]) for row in analysis.store.rows("location")}
    with sandbox.active(analysis.policy):  # inline suppressions are read where the analysis could read
        elements = {str(node): (loc[0], loc[1]) for node, _pkg, _exe, elem in analysis.store.rows("node")
                    if (loc := analysis.store.location(str(elem)))}
        unused = apply_suppressions(findings, files, root if root.is_dir() else root.parent, config.suppress,
                                    str(config.source or ""), elements)
    if fix or show_diff:
        findings = _fix(findings, analysis.store, rebase, unsafe_fixes, show_diff)
    hidden: dict[str, int] = {}
    if new_only:
        before = _base_fingerprints(given, base_ref)
        hidden[f"pre-existing in {base_ref}"] = sum(f.fingerprint in before for f in findings)
        findings = [f for f in findings if f.fingerprint not in before]
    if baseline:
        try:
            known = read_baseline(baseline)
        except ValueError as exc:
            raise click.UsageError(str(exc)) from None
        hidden["in the baseline"] = sum(f.fingerprint in known for f in findings)
        unused += stale_baseline(baseline, known, {f.fingerprint for f in findings})
        findings = [f for f in findings if f.fingerprint not in known]
    if write_baseline:
        written = write_baseline_file(findings, write_baseline)
        click.echo(f"archlog: wrote {written} finding{'s' if written != 1 else ''} to {write_baseline}", err=True)
    report = Report(findings, config.diagnostics(analysis.diagnostics.items + unused, verbose), config.adjust(ruleset.rules),
                    root, Report.node_origins(analysis.store) if fmt == "sarif" else {},  # (only SARIF lists them)
                    coverage(analysis.store), labels, hidden,
                    holes(analysis.store))
    report = rebase.report(report)
    if fmt == "concise":
        with output.open("w", encoding="utf-8") if output else nullcontext(sys.stdout) as stream:
            print_concise(report, stream)
    elif fmt == "text" and output:
        with output.open("w", encoding="utf-8") as fh, sandbox.active(analysis.policy):
            print_text(report, Console(file=fh, no_color=True, soft_wrap=True), quiet)
    elif fmt == "text":
        with sandbox.active(analysis.policy):  # the source lines it quotes
            print_text(report, Console(no_color=bool(os.environ.get("NO_COLOR")), soft_wrap=True), quiet)
    else:
        text = {"json": to_json, "sarif": to_sarif, "codequality": to_codequality, "github": to_github,
                "junit": to_junit}[fmt](report)
        if output:
            output.write_text(text, encoding="utf-8")
        else:
            sys.stdout.write(text)
    failed = fail_on_incomplete and report.incomplete
    if fail_on != "never" and not write_baseline:  # what was just recorded as accepted fails nothing
        worst = SEVERITIES[: SEVERITIES.index(fail_on) + 1]
        failed = failed or any(f.severity in worst and f.suppression is None for f in findings)
    sys.exit(1 if failed else 0)


def _base_fingerprints(given: Inputs, ref: str) -> set[str]:
    """The fingerprints of the findings of the same system in the git revision `ref`."""
    import tempfile
    from dataclasses import replace

    from archlog.queries.session import Session
    from archlog.reports import differential

    tree = differential.work_tree(given.paths[0])
    with tempfile.TemporaryDirectory(prefix="archlog-base-") as folder:
        dest = Path(folder)
        differential.checkout(tree, ref, dest)
        base = replace(given, paths=[differential.moved(p, tree, dest) for p in given.paths],
                       launches=[differential.moved_launch(lf, tree, dest) for lf in given.launches],
                       models=[differential.moved(m, tree, dest) for m in given.models])
        analysis = _analyse(base, quiet=True)
        return {f.fingerprint for f in Session(analysis.store, given.ruleset, given.config).findings()}


def _fix(findings: list, store, rebase, unsafe: bool, show_diff: bool) -> list:
    """Apply the fixes (or print them with `show_diff`, then exit); the findings left unfixed."""
    from archlog.reports import fixes

    planned = fixes.plan(findings, store, rebase.absolute)
    applied = fixes.chosen(planned, unsafe)
    changes = fixes.edited(applied)
    if show_diff:
        sys.stdout.write(fixes.unified(changes, lambda path: rebase(str(path))))
        sys.exit(1 if changes else 0)
    for path, (_before, after) in changes.items():
        path.write_text(after, encoding="utf-8")
    for done in applied:
        click.echo(f"fixed: {done.finding.rule.id} {done.what} ({rebase(str(done.edit.file))})", err=True)
    waiting = len([f for f in planned if not f.safe]) if not unsafe else 0
    click.echo(f"archlog: applied {len(applied)} fix{'es' if len(applied) != 1 else ''} in {len(changes)} "
               f"file{'s' if len(changes) != 1 else ''}" + (f"; {waiting} more with --unsafe-fixes" if waiting else ""),
               err=True)
    fixed = {id(done.finding) for done in applied}
    return [f for f in findings if id(f) not in fixed]


@main.command()
@_system_options
@click.option("--format", "fmt", type=click.Choice(["csv", "json"]), default="csv", show_default=True)
@click.argument("directory", type=click.Path(file_okay=False, path_type=Path))
def facts(paths, launches, args, models, rule_paths, config_path, profile, near_miss_threshold, env, fmt,
          directory) -> None:
    """Export the recovered facts, one file per relation, into DIRECTORY (the last argument)."""
    analysis, _ruleset, config = _load(paths, launches, args, models, rule_paths, config_path, profile,
                                       near_miss_threshold, env)
    written = analysis.store.export(directory, fmt)
    for diag in config.diagnostics(analysis.diagnostics.items):
        click.echo(str(diag), err=True)
    click.echo(f"wrote {len(written)} relations to {directory}", err=True)


@main.command()
@_system_options
@click.option("--format", "fmt", type=click.Choice(["table", "json", "csv"]), default="table", show_default=True)
@click.argument("goal")
def query(paths, launches, args, models, rule_paths, config_path, profile, near_miss_threshold, env, goal,
          fmt) -> None:
    """Print every binding of the variables of GOAL (the last argument: a conjunction of literals such
    as 'publisher(P, N, T, _), not subscribed(T)') over the facts and derived relations."""
    from archlog.queries.session import QueryError, Session
    from archlog.queries.table import print_result

    analysis, ruleset, config = _load(paths, launches, args, models, rule_paths, config_path, profile,
                                      near_miss_threshold, env)
    try:
        result = Session(analysis.store, ruleset, config).query(goal)
    except QueryError as exc:
        raise click.UsageError(str(exc)) from None
    print_result(result, fmt, sys.stdout)


@main.command()
@_system_options
def repl(paths, launches, args, models, rule_paths, config_path, profile, near_miss_threshold, env) -> None:
    """Interactive queries over the system: extraction runs once."""
    from archlog.queries.repl import run_repl
    from archlog.queries.session import Session

    analysis, ruleset, config = _load(paths, launches, args, models, rule_paths, config_path, profile,
                                      near_miss_threshold, env)
    run_repl(Session(analysis.store, ruleset, config), analysis)


@main.command()
@_system_options
@click.option("--format", "fmt", type=click.Choice(["dot", "svg", "html"]), default="html", show_default=True)
@click.option("--focus", help="Keep what is near this node, topic, service, action or parameter (its resolved name).")
@click.option("--depth", type=click.IntRange(0, 20), default=2, show_default=True,
              help="Edges around --focus (near-miss partners of what is kept are kept too).")
@click.option("--parameters", is_flag=True, help="dot, svg: draw parameters too (the HTML page toggles them).")
@click.option("--show", "groups", multiple=True, type=click.Choice(["tf", "dynamic_reconfigure", "rosout", "built-in",
              "leaf topics", "all"]), help="dot, svg: draw this infrastructure too, hidden unless a finding names "
              "it (repeatable; the HTML page toggles them).")
@click.option("--output", type=click.Path(dir_okay=False, path_type=Path), help="Write here instead of stdout.")
def graph(paths, launches, args, models, rule_paths, config_path, profile, near_miss_threshold, env, fmt, focus,
          depth, parameters, groups, output) -> None:
    """Draw the recovered architecture, with findings highlighted (an offline HTML page by default)."""
    from archlog.reports import graph as views
    from archlog.reports.paths import Rebase, source_root

    analysis, ruleset, config = _load(paths, launches, args, models, rule_paths, config_path, profile,
                                      near_miss_threshold, env, quiet=output is None)
    rebase = Rebase(analysis.workspace.roots, source_root(analysis.workspace.roots[0], None))
    drawn = views.build(analysis.store, _in_repository(analysis, ruleset, config, rebase)[0])
    if focus:
        try:
            drawn = views.focus(drawn, focus, depth)
        except ValueError as exc:
            raise click.UsageError(str(exc)) from None
    try:
        asked = set(views.GROUPS) - {"parameters"} if "all" in groups else set(groups)
        text = views.draw(drawn, fmt, f"archlog: {' '.join(map(str, analysis.workspace.roots))}",
                          asked | ({"parameters"} if parameters else set()))
    except RuntimeError as exc:
        raise click.ClickException(str(exc)) from None
    if output:
        output.write_text(text, encoding="utf-8")
    else:
        sys.stdout.write(text)


@main.command("observe")
@click.option("--master", "master_uri", default=lambda: os.environ.get("ROS_MASTER_URI", "http://127.0.0.1:11311"),
              show_default="$ROS_MASTER_URI", help="The running ROS 1 master to read.")
@click.option("--output", type=click.Path(dir_okay=False, path_type=Path), help="Write JSON here instead of stdout.")
@click.option("--write-models", type=click.Path(file_okay=False, path_type=Path),
              help="Also write an instance model per observed node into this folder.")
@click.option("--ros2-node-info", "node_info", multiple=True,
              type=click.Path(exists=True, dir_okay=False, path_type=Path),
              help="Read saved `ros2 node info NODE` output (repeatable) instead of a ROS 1 master.")
@click.option("--ros2", "ros2", is_flag=True,
              help="Read the live ROS 2 graph with rclpy (archlog's ros2 extra) instead of a ROS 1 master: every "
                   "port kind, and each topic endpoint's QoS.")
@click.option("--domain", type=click.IntRange(0, 232), default=None, show_default="$ROS_DOMAIN_ID",
              help="With --ros2: the DDS domain to read.")
@click.option("--settle", type=click.FloatRange(0.1, 60), default=2.0, show_default=True,
              help="With --ros2: seconds the graph must stay unchanged before it is read (discovery takes time).")
def observe_command(master_uri, output, write_models, node_info, ros2, domain, settle) -> None:
    """Read the live architecture (nodes, topics with types, services) from a running ROS 1 master
    or ROS 2 domain."""
    from archlog import observe

    if node_info:
        try:
            parts = [observe.read_ros2_node_info(p.read_text(encoding="utf-8"), str(p)) for p in node_info]
        except observe.NodeInfoError as exc:
            raise click.ClickException(str(exc)) from None
        observed = observe.Architecture.merged(parts)
    elif ros2:
        from archlog import observe_ros2

        try:
            observed = observe_ros2.read_graph(domain, settle=settle, timeout=settle + 20).architecture()
        except observe_ros2.Ros2Unavailable as exc:
            raise click.ClickException(str(exc)) from None
    else:
        try:
            observed = observe.read_master(observe.master(master_uri))
        except (OSError, RuntimeError) as exc:
            raise click.ClickException(f"cannot read the master at {master_uri}: {exc}") from None
    if write_models:
        for path in observe.write_models(observed, write_models):
            click.echo(f"wrote {path}", err=True)
    if output:
        output.write_text(observed.to_json(), encoding="utf-8")
    else:
        sys.stdout.write(observed.to_json())


@main.command()
@_system_options
@click.option("--observed", required=True, type=click.Path(exists=True, dir_okay=False, path_type=Path),
              help="A JSON file written by `archlog observe`.")
@click.option("--format", "fmt", type=click.Choice(["text", "json"]), default="text", show_default=True)
def diff(paths, launches, args, models, rule_paths, config_path, profile, near_miss_threshold, env, observed,
         fmt) -> None:
    """Compare the recovered architecture with an observed one (exit 1 when they differ)."""
    from rich.console import Console
    from rich.table import Table

    from archlog import observe

    analysis, _ruleset, _config = _load(paths, launches, args, models, rule_paths, config_path, profile,
                                        near_miss_threshold, env, quiet=True)
    try:
        seen = observe.Architecture.from_json(observed.read_text(encoding="utf-8"))
    except (ValueError, KeyError, TypeError) as exc:
        raise click.UsageError(f"{observed}: not an observed architecture ({exc})") from None
    result = observe.compare(observe.from_facts(analysis.store), seen)
    if fmt == "json":
        sys.stdout.write(json.dumps(result, indent=1) + "\n")
    else:
        table = Table("kind", "recovered", "observed", "over-approx. %", "under-approx. %")
        for kind, row in result.items():
            table.add_row(kind, str(row["recovered"]), str(row["observed"]), str(row["over_approximation"]),
                          str(row["under_approximation"]))
        console = Console(soft_wrap=True)
        console.print(table)
        for kind, row in result.items():
            for item in row["only_recovered"]:
                console.print(f"only recovered {kind}: {item}", markup=False)
            for item in row["only_observed"]:
                console.print(f"only observed {kind}: {item}", markup=False)
    sys.exit(1 if any(r["only_recovered"] or r["only_observed"] for r in result.values()) else 0)


@main.command()
@_system_options
@click.option("--format", "fmt", type=click.Choice(["text", "json"]), default="text", show_default=True)
def behavior(paths, launches, args, models, rule_paths, config_path, profile, near_miss_threshold, env,
             fmt) -> None:
    """Print each node's behavior: state, and the triggers, guards and required inputs of its outputs."""
    from rich.console import Console

    from archlog.queries.session import Session
    from archlog.reports.behavior import behavior_model, print_behavior

    analysis, ruleset, config = _load(paths, launches, args, models, rule_paths, config_path, profile,
                                      near_miss_threshold, env)
    model = behavior_model(analysis.store, Session(analysis.store, ruleset, config).ctl)
    if fmt == "json":
        sys.stdout.write(json.dumps({"nodes": model}, indent=1) + "\n")
    else:
        print_behavior(model, Console(soft_wrap=True))


@main.command()
@_system_options
@click.option("--nodes", "nodes", multiple=True, metavar="NAME", help="Test these nodes in isolation (repeatable).")
@click.option("--settings", "settings_path", type=click.Path(exists=True, dir_okay=False, path_type=Path),
              help="Testgen settings (TOML): fields, parameters, property switches.")
@click.option("--name", help="Name of the generated files [default: the first launch file's name].")
@click.option("--output", required=True, type=click.Path(file_okay=False, path_type=Path), help="Folder to write to.")
def testgen(paths, launches, args, models, rule_paths, config_path, profile, near_miss_threshold, env, nodes,
            settings_path, name, output) -> None:
    """Generate a property-based integration test (Hypothesis, pytest) for the configuration."""
    from archlog.queries.session import Session
    from archlog.testgen.command import testgen_command

    analysis, ruleset, config = _load(paths, launches, args, models, rule_paths, config_path, profile,
                                      near_miss_threshold, env, quiet=True)
    testgen_command(analysis, Session(analysis.store, ruleset, config).ctl, list(paths), list(launches),
                    _arg_pairs(args), list(nodes), settings_path, name, output)


@main.command()
@click.argument("file", type=click.Path(exists=True, dir_okay=False, path_type=Path))
def replay(file) -> None:
    """Run a replay file written by a failing generated test again (exit 1 when a property fails)."""
    from archlog.testgen.replay import replay_file

    sys.exit(0 if replay_file(file) else 1)


@main.command("test-rules")
@click.argument("folders", nargs=-1, required=True, type=click.Path(exists=True, file_okay=False, path_type=Path))
@click.option("--update", is_flag=True, help="Write the .expected files that differ from the current results "
              "(each file written is named).")
@click.option("--only", is_flag=True, help="Expect only the findings of the rules in FOLDERS: the shipped rules' "
              "findings are left out (their derived relations stay usable).")
def test_rules(folders, update, only) -> None:
    """Run each rule's fixtures and compare with their .expected files (exit 1 on a difference)."""
    from rich.console import Console

    from archlog.queries.rule_tests import run_rule_tests

    sys.exit(0 if run_rule_tests(list(folders), update, Console(soft_wrap=True), only) else 1)


@main.command("rule")
@click.argument("rule_id", metavar="[ID]", required=False)
@click.option("--rules", "rule_paths", multiple=True, type=click.Path(exists=True, path_type=Path),
              help="Extra rule file or folder of .lp files (repeatable), as for check.")
@click.option("--config", "config_path", type=click.Path(exists=True, dir_okay=False, path_type=Path),
              help="archlog.toml or pyproject.toml whose `rules` to include (default: found here or above).")
def rule_command(rule_id, rule_paths, config_path) -> None:
    """Explain a rule (id, id prefix or name): description, an example finding, how to fix it.
    Without ID, list every rule."""
    from archlog.config import find_config, load_config, workspace_config
    from archlog.reports.rule_help import listing, lookup
    from archlog.rules.ruleset import load_rules

    config = load_config(config_path or find_config([]), None)
    if config_path is None and config.source is not None:
        config = workspace_config(config)
    rules = load_rules([*config.rule_paths, *rule_paths]).rules
    try:
        click.echo(lookup(rules, rule_id) if rule_id else listing(rules), nl=False)
    except LookupError as exc:
        raise click.UsageError(str(exc.args[0])) from None



def run() -> None:
    """Entry point: configuration errors exit 2 with a one-line message, never a traceback."""
    try:
        main(standalone_mode=False)
    except click.exceptions.Abort:
        sys.exit(130)
    except click.ClickException as exc:
        exc.show()
        sys.exit(2)
    except (ConfigError, RuleError) as exc:
        click.echo(f"archlog: error: {exc}", err=True)
        sys.exit(2)
    except SystemExit:
        raise
    except Exception as exc:  # last resort: report, do not dump a traceback
        if os.environ.get("ARCHLOG_DEBUG"):
            raise
        click.echo(f"archlog: internal error: {type(exc).__name__}: {exc} (set ARCHLOG_DEBUG=1 for details)", err=True)
        sys.exit(2)
