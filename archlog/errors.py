"""Errors that end a run before any analysis: usage and configuration mistakes (exit status 2)."""

from __future__ import annotations


class ConfigError(Exception):
    """A usage or configuration error (exit status 2)."""
