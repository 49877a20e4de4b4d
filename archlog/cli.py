"""The `archlog` command line: check, facts."""

from __future__ import annotations

import os
import sys
from pathlib import Path

import click
from rich.console import Console

from archlog import __version__
from archlog.analysis import Analysis, ConfigError, analyse
from archlog.diagnostics import SEVERITIES
from archlog.reports.json_report import to_json
from archlog.reports.model import Report
from archlog.reports.sarif import to_sarif
from archlog.reports.text import print_text
from archlog.rules.engine import Engine
from archlog.rules.ruleset import RuleError, load_rules

FAIL_ON = (*SEVERITIES, "never")


def _arg_pairs(values: tuple[str, ...]) -> dict[str, str]:
    pairs = {}
    for value in values:
        if ":=" not in value:
            raise click.BadParameter(f"expected NAME:=VALUE, got {value!r}", param_hint="--arg")
        name, val = value.split(":=", 1)
        pairs[name] = val
    return pairs


def _system_options(func):
    options = [
        click.argument("paths", nargs=-1, required=True, type=click.Path(path_type=Path)),
        click.option("--launch", "launches", multiple=True, metavar="FILE_OR_PKG/FILE",
                     help="Launch file of the configuration (repeatable; together they form one system)."),
        click.option("--arg", "args", multiple=True, metavar="NAME:=VALUE", help="Launch argument (repeatable)."),
        click.option("--model", "models", multiple=True, type=click.Path(path_type=Path),
                     help="YAML node models for nodes without source, or external producers/consumers."),
        click.option("--near-miss-threshold", default=0.5, show_default=True, type=click.FloatRange(0, 5),
                     help="Normalised name distance below which two names are a near miss."),
    ]
    for option in reversed(options):
        func = option(func)
    return func


def _analyse(paths, launches, args, models, threshold) -> Analysis:
    return analyse(list(paths), list(launches), _arg_pairs(args), list(models), threshold)


@click.group(context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, prog_name="archlog")
def main() -> None:
    """Find architecture misconfigurations in ROS systems before the robot runs."""


@main.command()
@_system_options
@click.option("--rules", "rule_paths", multiple=True, type=click.Path(exists=True, path_type=Path),
              help="Extra rule file or folder of .lp files (repeatable).")
@click.option("--format", "fmt", type=click.Choice(["text", "json", "sarif"]), default="text", show_default=True)
@click.option("--output", type=click.Path(path_type=Path), help="Write the report here instead of stdout.")
@click.option("--fail-on", type=click.Choice(FAIL_ON), default="error", show_default=True,
              help="Exit 1 when a finding of this severity or worse exists.")
def check(paths, launches, args, models, near_miss_threshold, rule_paths, fmt, output, fail_on) -> None:
    """Check a ROS system configuration and report findings."""
    ruleset = load_rules(list(rule_paths))
    engine = Engine(ruleset)
    analysis = _analyse(paths, launches, args, models, near_miss_threshold)
    _ctl, findings = engine.run(analysis.store)
    report = Report(findings, analysis.diagnostics.items, ruleset.rules, analysis.workspace.roots[0])
    if fmt == "text" and output:
        with output.open("w", encoding="utf-8") as fh:
            print_text(report, Console(file=fh, no_color=True, soft_wrap=True))
    elif fmt == "text":
        print_text(report, Console(no_color=bool(os.environ.get("NO_COLOR")), soft_wrap=True))
    else:
        text = to_json(report) if fmt == "json" else to_sarif(report)
        if output:
            output.write_text(text, encoding="utf-8")
        else:
            sys.stdout.write(text)
    if fail_on != "never":
        worst = SEVERITIES[: SEVERITIES.index(fail_on) + 1]
        sys.exit(1 if any(f.severity in worst for f in findings) else 0)


@main.command()
@_system_options
@click.option("--format", "fmt", type=click.Choice(["csv", "json"]), default="csv", show_default=True)
@click.argument("directory", type=click.Path(file_okay=False, path_type=Path))
def facts(paths, launches, args, models, near_miss_threshold, fmt, directory) -> None:
    """Export the recovered facts, one file per relation, into DIRECTORY (the last argument)."""
    analysis = _analyse(paths, launches, args, models, near_miss_threshold)
    written = analysis.store.export(directory, fmt)
    for diag in analysis.diagnostics.items:
        click.echo(str(diag), err=True)
    click.echo(f"wrote {len(written)} relations to {directory}", err=True)


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
    except Exception as exc:  # noqa: BLE001 - last resort: report, do not dump a traceback
        if os.environ.get("ARCHLOG_DEBUG"):
            raise
        click.echo(f"archlog: internal error: {type(exc).__name__}: {exc} (set ARCHLOG_DEBUG=1 for details)", err=True)
        sys.exit(2)
