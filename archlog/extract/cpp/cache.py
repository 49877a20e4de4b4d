"""An on-disk store of per-file extraction results (SQLite), keyed by content and flags."""

from __future__ import annotations

import hashlib
import json
import os
import pickle
import sqlite3
from functools import lru_cache
from pathlib import Path

from archlog import __version__, budget


def cache_dir() -> Path:
    """$ARCHLOG_CACHE_DIR, else $XDG_CACHE_HOME/archlog, else ~/.cache/archlog."""
    base = os.environ.get("ARCHLOG_CACHE_DIR") or \
        Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache") / "archlog"
    path = Path(base)
    path.mkdir(parents=True, exist_ok=True)
    return path


@lru_cache(maxsize=1)
def code_digest() -> str:
    """Changes whenever archlog's extraction code changes, so cached results never outlive it."""
    digest = hashlib.sha256(__version__.encode())
    package = Path(__file__).resolve().parents[2]
    for path in sorted([*package.glob("extract/**/*.py"), package / "values.py", package / "names.py"]):
        digest.update(path.read_bytes())
    return digest.hexdigest()


def key(*parts: bytes | str) -> str:
    """A cache key over the extraction code and every input that changes a result."""
    digest = hashlib.sha256(code_digest().encode())
    for part in parts:
        digest.update(b"\0" + (part.encode() if isinstance(part, str) else part))
    return digest.hexdigest()


class ResultCache:
    """get/put of picklable results, each under its key and the budget in force (values fold
    within its limits); a damaged or missing store just misses."""

    def __init__(self, name: str) -> None:
        self.path = cache_dir() / f"{name}.sqlite"
        self._db: sqlite3.Connection | None = None

    def _connect(self) -> sqlite3.Connection:
        if self._db is None:
            self._db = sqlite3.connect(self.path, timeout=30)
            self._db.execute("CREATE TABLE IF NOT EXISTS results (key TEXT PRIMARY KEY, value BLOB)")
        return self._db

    def get(self, cache_key: str) -> object | None:
        try:
            row = self._connect().execute("SELECT value FROM results WHERE key = ?", (_scoped(cache_key),)).fetchone()
            return pickle.loads(row[0]) if row else None
        except (sqlite3.Error, pickle.PickleError, EOFError, AttributeError):
            return None

    def put(self, cache_key: str, value: object) -> None:
        try:
            with self._connect() as db:
                db.execute("INSERT OR REPLACE INTO results VALUES (?, ?)", (_scoped(cache_key), pickle.dumps(value)))
        except sqlite3.Error:
            return


def _scoped(cache_key: str) -> str:
    return key(cache_key, json.dumps(dict(budget.current().limits), sort_keys=True))
