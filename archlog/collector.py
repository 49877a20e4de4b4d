"""Python's cyclic garbage collector, paused while a stage builds many long-lived objects."""

from __future__ import annotations

import gc
from collections.abc import Iterator
from contextlib import contextmanager


@contextmanager
def paused() -> Iterator[None]:
    """No cyclic collection inside: building the fact store allocates hundreds of thousands of rows
    that all stay alive, and each collection the allocations trigger walks every row built so far.
    Reference counting still frees what it can; the collector runs again (as it was) afterwards."""
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if enabled:
            gc.enable()
