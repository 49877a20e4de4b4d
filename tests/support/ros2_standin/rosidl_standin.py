"""Message classes in the shape of rosidl_generator_py's: `get_fields_and_field_types()` and
setters that refuse what the generated classes refuse (the wrong Python type, an integer out of
range, a float32 beyond its range, a fixed array of the wrong length, a bound exceeded)."""

import importlib
import math

INT_RANGES = {"int8": (-2**7, 2**7 - 1), "uint8": (0, 2**8 - 1), "int16": (-2**15, 2**15 - 1),
              "uint16": (0, 2**16 - 1), "int32": (-2**31, 2**31 - 1), "uint32": (0, 2**32 - 1),
              "int64": (-2**63, 2**63 - 1), "uint64": (0, 2**64 - 1), "char": (0, 2**8 - 1)}
FLOAT_MAX = {"float": 3.402823466e+38, "double": 1.7976931348623157e+308}


def check(value, kind, where):
    """Raise AssertionError (as rosidl's setters do) unless `value` fits the rosidl type `kind`."""
    if kind.startswith("sequence<"):
        element, _, bound = kind[len("sequence<"):-1].partition(",")
        assert isinstance(value, (list, tuple)), f"{where}: a sequence, not {type(value).__name__}"
        assert not bound or len(value) <= int(bound), f"{where}: more than {bound} elements"
        for item in value:
            check(item, element.strip(), where)
    elif kind.endswith("]"):
        size = int(kind[kind.index("[") + 1:-1])
        assert isinstance(value, (list, tuple)) and len(value) == size, f"{where}: {size} elements"
        for item in value:
            check(item, kind[:kind.index("[")], where)
    elif kind in INT_RANGES:
        low, high = INT_RANGES[kind]
        assert isinstance(value, int) and not isinstance(value, bool) and low <= value <= high, f"{where}: {value!r}"
    elif kind in FLOAT_MAX:
        assert isinstance(value, float), f"{where}: {value!r} is not a float"
        assert math.isnan(value) or math.isinf(value) or abs(value) <= FLOAT_MAX[kind], f"{where}: {value!r}"
    elif kind == "boolean":
        assert isinstance(value, bool), f"{where}: {value!r}"
    elif kind == "octet":
        assert isinstance(value, bytes) and len(value) == 1, f"{where}: {value!r}"
    elif kind.startswith("string"):
        assert isinstance(value, str), f"{where}: {value!r}"
        assert kind == "string" or len(value) <= int(kind[len("string<"):-1]), f"{where}: too long"
    else:
        package, _, name = kind.partition("/")
        cls = getattr(importlib.import_module(f"{package}.msg"), name)
        assert isinstance(value, cls), f"{where}: {type(value).__name__} is not {kind}"


def default(kind):
    if kind.startswith("sequence<"):
        return []
    if kind.endswith("]"):
        return [default(kind[:kind.index("[")])] * int(kind[kind.index("[") + 1:-1])
    if kind in INT_RANGES:
        return 0
    if kind in FLOAT_MAX:
        return 0.0
    return {"boolean": False, "octet": b"\0"}.get(kind, "" if kind.startswith("string") else None)


class Message:
    _fields_and_field_types: dict = {}

    def __init__(self):
        for name, kind in self._fields_and_field_types.items():
            value = default(kind)
            if value is None:
                package, _, cls = kind.partition("/")
                value = getattr(importlib.import_module(f"{package}.msg"), cls)()
            object.__setattr__(self, name, value)

    @classmethod
    def get_fields_and_field_types(cls):
        return dict(cls._fields_and_field_types)

    def __setattr__(self, name, value):
        assert name in self._fields_and_field_types, f"{type(self).__name__} has no field {name}"
        check(value, self._fields_and_field_types[name], f"{type(self).__name__}.{name}")
        object.__setattr__(self, name, value)
