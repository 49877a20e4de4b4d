"""Command-line choices over archlog.toml, one mechanism with the file's keys:

- `--select`, `--extend-select`, `--ignore` take what `select` and `ignore` take (rule ids, id
  prefixes, rule names, tags, diagnostic codes, code prefixes such as `launch-`), comma-separated
  or repeated. `--select` replaces the configuration's `select`; the other two add to it.
- `--system NAME` runs the `[systems.NAME]` table: its paths, launch files, arguments and models
  come before those given on the command line (an `--arg` wins over the table's `args`).

Every command that reads a system takes them (`system_options` in cli.py); `_load` applies them.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field, replace
from pathlib import Path

import click

from archlog.config import Config, is_code
from archlog.errors import ConfigError
from archlog.rules.ruleset import Rule

KEY = "archlog.choices"


@dataclass
class Choices:
    select: list[str] | None = None  # None: the configuration's select
    extend_select: list[str] = field(default_factory=list)
    ignore: list[str] = field(default_factory=list)
    system: str | None = None


def _store(name: str) -> Callable:
    def callback(ctx: click.Context, _param: click.Parameter, value: str | tuple[str, ...] | None) -> None:
        choices = ctx.meta.setdefault(KEY, Choices())
        if isinstance(value, str) or value is None:
            choices.system = value
        elif value:
            setattr(choices, name, [p.strip() for v in value for p in v.split(",") if p.strip()])
    return callback


def options(func: Callable) -> Callable:
    """The choice options; their values reach `given()` instead of the command's arguments."""
    pattern = "ID,PREFIX,NAME,TAG,CODE"
    for option in reversed([
        click.option("--select", multiple=True, metavar=pattern, expose_value=False, callback=_store("select"),
                     help="Run only these rules and diagnostic codes (replaces `select` of archlog.toml)."),
        click.option("--extend-select", multiple=True, metavar=pattern, expose_value=False,
                     callback=_store("extend_select"), help="Add to the selection of archlog.toml."),
        click.option("--ignore", multiple=True, metavar=pattern, expose_value=False, callback=_store("ignore"),
                     help="Leave out these rules and diagnostic codes (added to `ignore` of archlog.toml)."),
        click.option("--system", metavar="NAME", expose_value=False, callback=_store("system"),
                     help="Run the system configuration [systems.NAME] of archlog.toml."),
    ]):
        func = option(func)
    return func


def given() -> Choices:
    """The choices of the running command (none outside one)."""
    ctx = click.get_current_context(silent=True)
    return ctx.meta.get(KEY, Choices()) if ctx is not None else Choices()


def select(config: Config, choices: Choices, rules: list[Rule]) -> Config:
    """The configuration with the command line's selection; a pattern that names nothing is an error."""
    for pattern in [*(choices.select or []), *choices.extend_select, *choices.ignore]:
        if not is_code(pattern) and not any(pattern in (r.id, r.name, *r.tags) or r.id.startswith(pattern)
                                            for r in rules):
            raise click.BadParameter(f"'{pattern}' names no rule id, name or tag and no diagnostic code "
                                     "(`archlog rule` lists the rules, docs/diagnostics.md the codes)",
                                     param_hint="--select/--extend-select/--ignore")
    chosen = config.select if choices.select is None else choices.select
    return replace(config, select=[*chosen, *choices.extend_select], ignore=[*config.ignore, *choices.ignore])


def inputs(config: Config, choices: Choices, paths: list[Path], launches: list[str], args: dict[str, str],
           models: list[Path]) -> tuple[list[Path], list[str], dict[str, str], list[Path]]:
    """Paths, launch files, arguments and models of the run: the named system's, then the command
    line's, then the configuration's operator tools."""
    models = [*models, *config.operators]
    if choices.system is not None:
        if choices.system not in config.systems:
            known = ", ".join(sorted(config.systems)) or f"none in {config.source or 'any archlog.toml'}"
            raise ConfigError(f"unknown system '{choices.system}' (known: {known})")
        system = config.systems[choices.system]
        paths, launches = [*system.paths, *paths], [*system.launch, *launches]
        args, models = {**system.args, **args}, [*system.models, *models]
    if not paths and len(config.systems) == 1:  # the repository's one named system
        system = next(iter(config.systems.values()))
        paths, launches = [*system.paths], [*system.launch, *launches]
        args, models = {**system.args, **args}, [*system.models, *models]
    elif not paths and config.systems:
        raise click.UsageError(f"give PATH... or --system NAME (one of {', '.join(sorted(config.systems))})")
    elif not paths:  # the folder of archlog.toml, else the current one: its packages as rosrun starts them
        paths = [config.source.parent if config.source is not None else Path(".")]
    return paths, launches, args, list(dict.fromkeys(models))  # an operator named twice is one instance
