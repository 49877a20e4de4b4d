"""A node's command-line words: positional arguments and the values of options that take one."""

from __future__ import annotations


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
