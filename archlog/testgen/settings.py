"""The testgen settings file (TOML): switches for the built-in properties, timing, and per-field and
per-parameter choices. Every key is optional; an unknown key is an error naming its line.

    [testgen]
    specials = true          # NaN, +-inf and -0.0 in float fields
    max_array = 8            # longest variable-length array drawn
    settle = 0.2             # seconds waited after the last step before the final checks
    response_bound = 2.0     # seconds within which an output follows its required input
    period_tolerance = 0.5   # a periodic output may be this fraction slower than recovered
    reuse = false            # keep the nodes up across examples (only for stateless nodes)
    max_messages = 6         # at most this many rule steps per example

    [properties]             # the built-in properties, each on by default
    alive = true             # every node under test keeps its process and master registration
    interface = true         # the live graph of the nodes under test equals the recovered one
    periodic = true          # periodic outputs keep their recovered period
    requires = true          # an output requiring input X is silent until X, then starts in time
    callbacks = true         # no node under test logs an exception raised in a callback (rospy)

    [fields."pkg/Type".field]    # one field of a message type, wherever the type is used
    min = 0                      # bounds of a number
    max = 10
    values = [1, 2, 3]           # draw from these values only
    enum = true                  # draw from the type's constants of the field's type
    fixed = 4                    # always this value
    counter = true               # the topic's sequence number (1, 2, ...; a dropped message skips one)
    max_size = 4                 # longest array or string
    specials = false             # no NaN/inf for this float field

    [params."/node/name"]        # a parameter as an input (opt-in): set before launch
    values = [0, 1, 2]           # or min/max for a number, typed from the recovered default
    min = 0
    max = 10
"""

from __future__ import annotations

import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

TESTGEN = {"specials": bool, "max_array": int, "settle": float, "response_bound": float, "period_tolerance": float,
           "reuse": bool, "max_messages": int}
PROPERTIES = ("alive", "interface", "periodic", "requires", "callbacks")
FIELD_KEYS = {"min", "max", "values", "enum", "fixed", "counter", "max_size", "specials"}
PARAM_KEYS = {"values", "min", "max"}


class SettingsError(ValueError):
    """A settings file that does not parse or names an unknown key; the message starts file:line."""


@dataclass
class Settings:
    specials: bool = True
    max_array: int = 8
    settle: float = 0.2
    response_bound: float = 2.0
    period_tolerance: float = 0.5
    reuse: bool = False
    max_messages: int = 6  # a shrink attempt is a run of the system: fewer steps, fewer to make trivial
    properties: dict[str, bool] = field(default_factory=lambda: dict.fromkeys(PROPERTIES, True))
    fields: dict[str, dict[str, dict[str, Any]]] = field(default_factory=dict)
    params: dict[str, dict[str, Any]] = field(default_factory=dict)

    def to_dict(self) -> dict[str, Any]:
        return dict(self.__dict__)

    @classmethod
    def from_dict(cls, data: dict[str, Any]) -> Settings:
        """Settings written by to_dict (a property added since then is on)."""
        settings = cls(**{k: v for k, v in data.items() if k != "properties"})
        settings.properties.update(data.get("properties", {}))
        return settings


def load_settings(path: Path | None) -> Settings:
    """The settings in `path` (defaults without one); SettingsError on a bad file."""
    settings = Settings()
    if path is None:
        return settings
    text = path.read_text(encoding="utf-8")
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        line = getattr(exc, "lineno", None) or _line_of(str(exc))
        raise SettingsError(f"{path}:{line}: {exc}") from None

    def bad(key: str, why: str) -> SettingsError:
        return SettingsError(f"{path}:{_find(text, key)}: {why}: {key}")

    for section in data:
        if section not in ("testgen", "properties", "fields", "params"):
            raise bad(section, "unknown section")
    for key, value in data.get("testgen", {}).items():
        if key not in TESTGEN:
            raise bad(key, "unknown setting")
        want = TESTGEN[key]
        if not isinstance(value, want) and not (want is float and isinstance(value, int) and not isinstance(value, bool)):
            raise bad(key, f"expected a {want.__name__}")
        setattr(settings, key, want(value))
    for key, value in data.get("properties", {}).items():
        if key not in PROPERTIES or not isinstance(value, bool):
            raise bad(key, "unknown property or not true/false")
        settings.properties[key] = value
    for type_, fields in data.get("fields", {}).items():
        for name, options in fields.items():
            if not isinstance(options, dict) or set(options) - FIELD_KEYS:
                raise bad(name, f"field settings take {', '.join(sorted(FIELD_KEYS))}")
        settings.fields[type_] = fields
    for name, options in data.get("params", {}).items():
        if not isinstance(options, dict) or set(options) - PARAM_KEYS or not options:
            raise bad(name, f"parameter settings take {', '.join(sorted(PARAM_KEYS))}")
        settings.params[name] = options
    return settings


def _find(text: str, key: str) -> int:
    """The first line naming `key` (1 when none does)."""
    return next((n for n, line in enumerate(text.splitlines(), 1) if key in line), 1)


def _line_of(message: str) -> int:
    words = message.replace(",", " ").split()
    return next((int(w) for a, w in zip(words, words[1:]) if a == "line" and w.isdigit()), 1)
