"""Hypothesis strategies for ROS 1 messages, built from message specs (see msgspec.py) and the
field settings. A message is drawn as a dict (arrays as lists, `time`/`duration` as
{"secs", "nsecs"}); a Header's stamp is {"now": offset}, resolved by the bridge when the message
is published, so that it is near the time it is sent. One strategy per type, shared."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any, TypeVar

from hypothesis import strategies as st

from archlog.testgen.msgspec import Specs
from archlog.testgen.settings import Settings

T = TypeVar("T")
COUNTER = "__counter__"  # a field the machine fills with the topic's sequence counter when sending
INTS = {"byte": (-2**7, 2**7 - 1), "char": (0, 2**8 - 1), "int8": (-2**7, 2**7 - 1), "uint8": (0, 2**8 - 1),
        "int16": (-2**15, 2**15 - 1), "uint16": (0, 2**16 - 1), "int32": (-2**31, 2**31 - 1),
        "uint32": (0, 2**32 - 1), "int64": (-2**63, 2**63 - 1), "uint64": (0, 2**64 - 1)}
NSECS = (0, 999_999_999)
SPECIALS = (math.nan, math.inf, -math.inf, -0.0)
STRING_SIZE = 16  # longest string drawn unless the field's settings say otherwise


class Strategies:
    """Strategies per message type (cached), for one set of specs and settings."""

    def __init__(self, specs: Specs, settings: Settings) -> None:
        self.specs, self.settings = specs, settings
        self._cache: dict[str, st.SearchStrategy] = {}

    def message(self, type_: str) -> st.SearchStrategy:
        if type_ not in self._cache:
            self._cache[type_] = st.deferred(lambda: self._build(type_))
        return self._cache[type_]

    def _build(self, type_: str) -> st.SearchStrategy:
        spec = self.specs.get(type_, {"fields": [], "constants": {}})
        if type_ in ("std_msgs/Header", "std_msgs/msg/Header"):  # ROS 1's has a seq, ROS 2's none
            seq = {"seq": st.just(0)} if type_ == "std_msgs/Header" else {}
            return st.fixed_dictionaries({**seq, "stamp": stamp_near_now(),
                                          "frame_id": self._field(type_, ["frame_id", "string", None], spec)})
        return st.fixed_dictionaries({name: self._field(type_, [name, base, size], spec)
                                      for name, base, size in spec["fields"]})

    def _field(self, type_: str, field: list, spec: dict) -> st.SearchStrategy:
        name, base, size = field
        options: dict[str, Any] = self.settings.fields.get(type_, {}).get(name, {})
        if name in spec.get("bounds", {}):  # ROS 2's string<=N and T[<=N]
            longest = options.get("max_size", self.settings.max_array if size is not None else STRING_SIZE)
            options = {**options, "max_size": min(int(longest), spec["bounds"][name])}
        if "fixed" in options:
            return st.just(options["fixed"])
        if options.get("counter"):
            return st.just(COUNTER)
        if "values" in options:
            return pick(options["values"])
        if options.get("enum"):
            values = [v for b, v in spec["constants"].values() if b == base]
            if values:
                return pick(values)
        element = self.scalar(base, options)
        if size is None:
            return element
        if base in ("uint8", "char"):  # bytes in rospy; drawn as a list of ints all the same
            element = st.integers(0, 255)
        if size >= 0:
            return st.lists(element, min_size=size, max_size=size)
        return st.lists(element, max_size=int(options.get("max_size", self.settings.max_array)))

    def scalar(self, base: str, options: dict[str, Any]) -> st.SearchStrategy:
        """A value of a builtin type in its exact range (narrowed by `min`/`max`), or a nested message."""
        low, high = options.get("min"), options.get("max")
        if base == "bool":
            return st.booleans()
        if base in INTS:
            lo, hi = INTS[base]
            lo, hi = max(lo, low) if low is not None else lo, min(hi, high) if high is not None else hi
            # a quarter of the draws are a boundary: the ends of the range, 0, 1, -1
            edges = sorted({v for v in (lo, hi, 0, 1, -1) if lo <= v <= hi})
            return boosted(st.integers(lo, hi), edges)
        if base in ("float32", "float64"):
            specials = options.get("specials", self.settings.specials) and low is None and high is None
            floats = st.floats(low, high, allow_nan=specials, allow_infinity=specials, width=32 if base == "float32" else 64)
            # Hypothesis draws NaN and infinities rarely; a quarter of the draws are one of them (or -0.0)
            return boosted(floats, SPECIALS) if specials else floats
        if base == "string":
            return st.text(max_size=int(options.get("max_size", STRING_SIZE)))
        if base == "time":
            return st.fixed_dictionaries({"secs": st.integers(*INTS["uint32"]), "nsecs": st.integers(*NSECS)})
        if base == "duration":
            return st.fixed_dictionaries({"secs": st.integers(*INTS["int32"]), "nsecs": st.integers(*NSECS)})
        return self.message(base)


def pick(values: Sequence[T]) -> st.SearchStrategy[T]:
    """One of `values`, shrinking towards the first. Drawn from a 1-based index rather than with
    sampled_from or one_of: Hypothesis's first shrink pass retries every 0-based choice as a possible
    one_of branch, one run of the system each (a second or more here), and a message of a dozen
    fields used the whole shrink budget before any step was removed."""
    return st.integers(1, len(values)).map(lambda i: values[i - 1])


def boosted(plain: st.SearchStrategy[T], specials: Sequence[T]) -> st.SearchStrategy[T]:
    """`plain`, or in a quarter of the draws one of `specials`; shrinks towards `plain` (a 1-based
    branch, as in `pick`)."""
    return st.integers(1, 4).flatmap(lambda branch: pick(specials) if branch == 4 else plain)


def stamp_near_now(low: float = -0.5, high: float = 0.0) -> st.SearchStrategy:
    """A Header stamp `offset` seconds from the moment the message is sent."""
    return st.builds(lambda offset: {"now": offset}, st.floats(low, high))


def fill_counters(message: Any, value: int) -> Any:
    """`message` with every counter field set to `value`."""
    if message == COUNTER:
        return value
    if isinstance(message, dict):
        return {k: fill_counters(v, value) for k, v in message.items()}
    return message


def stale(message: Any, age: float) -> Any:
    """`message` with every Header stamp moved `age` seconds into the past."""
    if isinstance(message, dict):
        if set(message) == {"now"}:
            return {"now": message["now"] - age}
        return {k: stale(v, age) for k, v in message.items()}
    if isinstance(message, list):
        return [stale(v, age) for v in message]
    return message
