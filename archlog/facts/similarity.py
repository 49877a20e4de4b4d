"""Near-miss names: segment-aware Damerau-Levenshtein distance with a prefix-filtered join.

Names are split on '/' and '_' (an absolute name keeps its empty root segment). Substituting one
segment for another costs the character-level Damerau-Levenshtein distance of the two;
inserting or deleting a segment costs 1.5 and transposing two neighbours costs 1. The sum is
divided by the mean segment count. Two names are near misses when that is below the threshold
(default 0.5). The insertion cost makes replacing a whole segment (delete + insert) cost 3, as
much as three character edits, so /a/point and /a/line stay apart while /a/point and
/a/point_class, or /base_waypoint and /base_waypoints, are near.

Measuring costs the product of two names' segment counts (and of two segments' lengths), so names
past `MAX_SEGMENTS` segments or `MAX_CHARACTERS` characters (no ROS name comes near either) are not
compared: `too_long()` says which, and why.
"""

from __future__ import annotations

import re
from collections.abc import Iterable

import numpy as np
from rapidfuzz import process
from rapidfuzz.distance import OSA, DamerauLevenshtein

_SPLIT = re.compile(r"[/_]")
INDEL = 1.5
_BLOCK = 1024
MAX_SEGMENTS = 64
MAX_CHARACTERS = 1024


def segments(name: str) -> list[str]:
    return _SPLIT.split(name)


def too_long(name: str) -> str | None:
    """Why a name is not compared with others (too many segments or characters), or None."""
    if len(name) > MAX_CHARACTERS:
        return f"{len(name)} characters, over the {MAX_CHARACTERS}-character cap for near-miss comparison"
    count = name.count("/") + name.count("_") + 1
    if count > MAX_SEGMENTS:
        return f"{count} segments, over the {MAX_SEGMENTS}-segment cap for near-miss comparison"
    return None


def distance(a: str, b: str) -> float:
    """The normalised segment distance of two names."""
    return _Measure([a, b]).distances(np.array([0]), np.array([1]))[0]


def near_pairs(names: Iterable[str], threshold: float = 0.5) -> list[tuple[str, str, float]]:
    """Every unordered pair of distinct names whose distance is below `threshold` (names that are
    `too_long()` are left out).

    Each segment is encoded as one character, so rapidfuzz's optimal-string-alignment distance
    over the encoded names (every segment edit counted 1) bounds the real distance from below.
    That bound runs in C over all pairs, a block of rows at a time; only pairs under it are
    measured exactly, all at once.
    """
    measure = _Measure(sorted({name for name in names if too_long(name) is None}))
    lengths = measure.lengths
    first, second = [], []
    for start in range(0, len(measure.names), _BLOCK):
        rows = slice(start, start + _BLOCK)
        bound = process.cdist(measure.encoded[rows], measure.encoded, scorer=OSA.distance, dtype=np.float32, workers=-1)
        bound -= lengths[rows, None] * (threshold / 2)
        i, j = np.nonzero(bound < lengths[None, :] * (threshold / 2))
        i += start
        first.append(i[i < j])
        second.append(j[i < j])
    i, j = (np.concatenate(first), np.concatenate(second)) if first else (np.array([], int), np.array([], int))
    scores = measure.distances(i, j, threshold)
    keep = scores < threshold
    return sorted((measure.names[a], measure.names[b], float(d)) for a, b, d in zip(i[keep], j[keep], scores[keep]))


class _Measure:
    """Names as arrays of segment codes, and the character distance of every two segments."""

    def __init__(self, names: list[str]) -> None:
        self.names = names
        split = [segments(n) for n in names]
        vocabulary: dict[str, int] = {}
        codes = [[vocabulary.setdefault(seg, len(vocabulary)) for seg in segs] for segs in split]
        self.encoded = ["".join(chr(0x100 + c) for c in row) for row in codes]
        self.lengths = np.array([len(row) for row in codes], dtype=np.float32)
        width = max((len(row) for row in codes), default=0)
        self.codes = np.full((len(codes), width), -1, dtype=np.int64)
        for k, row in enumerate(codes):
            self.codes[k, : len(row)] = row
        words = list(vocabulary)
        self.cost = process.cdist(words, words, scorer=DamerauLevenshtein.distance, dtype=np.float32, workers=-1)

    def distances(self, first: np.ndarray, second: np.ndarray, limit: float | None = None) -> np.ndarray:
        """Normalised segment distances of the pairs (first[k], second[k]); with `limit`, values
        at or above it may come back as infinity."""
        result = np.zeros(len(first))
        la_all, lb_all = self.lengths[first].astype(int), self.lengths[second].astype(int)
        for la, lb in set(zip(la_all.tolist(), lb_all.tolist())):
            ks = np.nonzero((la_all == la) & (lb_all == lb))[0]
            budget = None if limit is None else limit * (la + lb) / 2
            dist = _dl(self.codes[first[ks], :la], self.codes[second[ks], :lb], self.cost, budget)
            result[ks] = dist * 2 / (la + lb)
        return result


def _dl(left: np.ndarray, right: np.ndarray, cost: np.ndarray, budget: float | None) -> np.ndarray:
    """Damerau-Levenshtein (optimal string alignment) over segment codes, vectorised over pairs.
    With a budget, cells that only paths costing at least the budget can cross are skipped."""
    pairs, la, lb = left.shape[0], left.shape[1], right.shape[1]
    sub = cost[left[:, :, None], right[:, None, :]]
    d = np.full((pairs, la + 1, lb + 1), np.inf, dtype=np.float32)
    d[:, :, 0] = np.arange(la + 1) * INDEL
    d[:, 0, :] = np.arange(lb + 1) * INDEL
    for i in range(1, la + 1):
        for j in range(1, lb + 1):
            if budget is not None and INDEL * (abs(i - j) + abs((la - i) - (lb - j))) >= budget:
                continue
            step = np.minimum(d[:, i - 1, j], d[:, i, j - 1]) + INDEL
            best = np.minimum(step, d[:, i - 1, j - 1] + sub[:, i - 1, j - 1])
            if i > 1 and j > 1:
                swapped = (left[:, i - 1] == right[:, j - 2]) & (left[:, i - 2] == right[:, j - 1])
                best = np.where(swapped, np.minimum(best, d[:, i - 2, j - 2] + 1), best)
            d[:, i, j] = best
    return d[:, la, lb]
