"""`archlog testgen`: the test model of the configuration, written as a generated test."""

from __future__ import annotations

import re
import sys
from pathlib import Path

import click
import clingo

from archlog.analysis import Analysis
from archlog.testgen.generate import write_test
from archlog.testgen.model import ModelError, test_model
from archlog.testgen.settings import SettingsError, load_settings


def testgen_command(analysis: Analysis, ctl: clingo.Control, paths: list[Path], launches: list[str],
                    args: dict[str, str], nodes: list[str], settings_path: Path | None, name: str | None,
                    output: Path) -> None:
    """Write the test; a bad settings file or node name is a usage error (exit 2), no traceback."""
    if not launches:
        raise click.UsageError("testgen needs the configuration's launch file(s) (--launch)")
    try:
        settings = load_settings(settings_path)
        model = test_model(analysis, ctl, paths, launches, args, nodes or None)
    except (SettingsError, ModelError) as exc:
        raise click.UsageError(str(exc)) from None
    for diagnostic in analysis.diagnostics.items:
        if diagnostic.code.startswith("testgen"):
            click.echo(str(diagnostic), err=True)
    if not any(model[part] for part in ("inputs", "outputs", "services", "actions")):
        raise click.UsageError("the nodes under test have no open input, output, service nor action to test (try --nodes)")
    stem = name or Path(launches[0]).name.split(".")[0]
    written = write_test(model, settings, output, re.sub(r"\W", "_", stem))
    for path in written:
        click.echo(f"wrote {path}")
    click.echo(f"{len(model['inputs'])} open input(s), {len(model['outputs'])} watched output(s), "
               f"{len(model['services'])} open service(s), {len(model['actions'])} open action(s); "
               f"run: python -m pytest {output}", file=sys.stdout)
