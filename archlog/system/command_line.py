"""A node's command-line words: positional arguments and the values of options that take one."""

from __future__ import annotations

import shlex

from archlog.values import CommandArg, Concat, Switch, Value, concat


def split_options(words: list[str], valued: set[str]) -> tuple[list[str], dict[str, str]]:
    """Positional words and {option: value} for the options in `valued`; flags and remap words
    (`a:=b`) are skipped."""
    positional: list[str] = []
    options: dict[str, str] = {}
    pending = None
    for word in words:
        if pending:
            options[pending], pending = word, None
        elif word in valued:
            pending = word
        elif not word.startswith("-") and ":=" not in word:
            positional.append(word)
    return positional, options


def command_value(value: Value, args: str) -> Value:
    """A value with each command-line argument in it replaced by what the command line `args`
    gives it (its default when the line lacks it), and each test of one decided."""
    if isinstance(value, CommandArg):
        given = command_word(value, args)
        return given if given is not None else command_value(value.default, args)
    if isinstance(value, Switch) and isinstance(subject := command_value(value.subject, args), str):
        return command_value(value.when_equal if subject == value.equals else value.otherwise, args)
    if isinstance(value, Concat):
        return concat(*[command_value(p, args) for p in value.parts])
    return value


def command_word(arg: CommandArg, args: str) -> str | None:
    """The word a command line `args` gives an argument: the `position`-th positional word (from 1),
    the value of one of its options (`--opt value` or `--opt=value`, the last one given, as argparse
    keeps it), or for a flag its `present` value; None when the line lacks it or cannot be split."""
    try:
        words = shlex.split(args)
    except ValueError:
        return None
    options = arg.options
    if not options:
        positional, _values = split_options(words, set(arg.valued))
        return positional[arg.position - 1] if len(positional) >= arg.position else None
    if arg.present is not None:
        return arg.present if any(w in options for w in words) else None
    found = None
    for word, following in zip(words, [*words[1:], None]):
        if word in options:
            found = following
        elif "=" in word and word.split("=", 1)[0] in options:
            found = word.split("=", 1)[1]
    return found
