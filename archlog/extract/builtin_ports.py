"""The table of the ports a ROS 2 node has because of its client library
(archlog/models/infrastructure/ros2.yaml): system/infrastructure.py adds them to every ROS 2 node,
and extractors name ports after it (the parameter services an AsyncParameterClient calls)."""

from __future__ import annotations

import functools
from dataclasses import dataclass
from pathlib import Path

import yaml

DATA = Path(__file__).resolve().parent.parent / "models" / "infrastructure" / "ros2.yaml"
_KINDS = {"publishers": "publisher", "subscribers": "subscriber", "services": "service_server"}


@dataclass(frozen=True)
class Group:
    """One group of built-in ports: (kind, name, type) each, from distribution `since` on."""

    name: str
    ports: tuple[tuple[str, str, str], ...]
    since: str | None


@dataclass(frozen=True)
class Builtin:
    """The groups, which of them every node has, and the distributions in release order."""

    groups: dict[str, Group]
    default: tuple[str, ...]
    distros: tuple[str, ...]


@functools.cache
def builtin() -> Builtin:
    """The shipped table of built-in ports."""
    data = yaml.safe_load(DATA.read_text())
    groups = {name: Group(name, tuple((_KINDS[key], p["name"], p["type"]) for key in _KINDS
                                      for p in entry.get(key, [])), entry.get("since"))
              for name, entry in data["groups"].items()}
    return Builtin(groups, tuple(data["default"]), tuple(data["distros"]))
