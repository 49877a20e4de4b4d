"""`python -m archlog` is the `archlog` command."""

from archlog.cli import run

run()
