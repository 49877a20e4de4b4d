"""Near-miss names: segment-aware Damerau-Levenshtein distance, joined through segment deletions.

Names are split on '/' and '_' (an absolute name keeps its empty root segment). Substituting one
segment for another costs the character-level Damerau-Levenshtein distance of the two;
inserting or deleting a segment costs 1.5 and transposing two neighbours costs 1. The sum is
divided by the mean segment count. Two names are near misses when that is below the threshold
(default 0.5). The insertion cost makes replacing a whole segment (delete + insert) cost 3, as
much as three character edits, so /a/point and /a/line stay apart while /a/point and
/a/point_class, or /base_waypoint and /base_waypoints, are near.

Numbers tell instances apart: two names whose numbers (their digit runs, in order) differ are
never near, so /robot_3/scan is not a typo of /robot_4/scan, nor camera1 of camera2.

Measuring costs the product of two names' segment counts (and of two segments' lengths), so names
past `MAX_SEGMENTS` segments or `MAX_CHARACTERS` characters (no ROS name comes near either) are not
compared: `too_long()` says which, and why.
"""

from __future__ import annotations

import math
import re
from collections import defaultdict
from collections.abc import Iterable

import numpy as np
from rapidfuzz.distance import DamerauLevenshtein

_SPLIT = re.compile(r"[/_]")
_NUMBER = re.compile(r"\d+")
INDEL = 1.5
MAX_SEGMENTS = 64
MAX_CHARACTERS = 1024
_MAX_KEYS = 512  # a name with more deletion keys than this is compared with every name of its group


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
    """The normalised segment distance of two names (infinite when their numbers differ)."""
    if _NUMBER.findall(a) != _NUMBER.findall(b):
        return math.inf
    return float(_Measure([a, b]).distances(np.array([0]), np.array([1]))[0])


def near_pairs(names: Iterable[str], threshold: float = 0.5) -> list[tuple[str, str, float]]:
    """Every unordered pair of distinct names whose distance is below `threshold` (names that are
    `too_long()` are left out)."""
    listed = list(names)
    return near_names(listed, listed, threshold)


def near_names(queries: Iterable[str], names: Iterable[str], threshold: float = 0.5) -> list[tuple[str, str, float]]:
    """Every unordered pair (a, b), a < b, of a name of `queries` and another name of `queries` or
    `names` whose distance is below `threshold`, sorted; names that are `too_long()` are left out.

    Candidates come from deletion neighbourhoods: a near pair is at most k segment edits apart
    (k follows from the threshold and the two lengths, as every edit costs at least 1), so deleting
    at most k segments from each name makes them equal. Each query's neighbourhood is indexed,
    every name's is looked up, and only the pairs that meet are measured, all at once. Names are
    grouped by their numbers first (names whose numbers differ are never near), so copies of one
    name under many numbered namespaces are never candidates of one another.
    """
    asked = {q for q in queries if too_long(q) is None}
    measure = _Measure(sorted(asked | {n for n in names if too_long(n) is None}))
    groups: dict[tuple[str, ...], list[int]] = defaultdict(list)
    for index, name in enumerate(measure.names):
        groups[tuple(_NUMBER.findall(name))].append(index)
    pairs: set[tuple[int, int]] = set()
    for members in groups.values():
        pairs |= _candidates(measure, members, [i for i in members if measure.names[i] in asked], threshold)
    if not pairs:
        return []
    i, j = (np.array(column) for column in zip(*sorted(pairs)))
    scores = measure.distances(i, j, threshold)
    keep = scores < threshold
    return [(measure.names[a], measure.names[b], float(d)) for a, b, d in zip(i[keep], j[keep], scores[keep])]


def _candidates(measure: _Measure, members: list[int], asked: list[int], threshold: float) -> set[tuple[int, int]]:
    """Pairs (i < j) of a name of `asked` and another of `members` that share a deletion key."""
    if not asked:
        return set()
    index: dict[str, list[int]] = defaultdict(list)
    wide = []
    for i in asked:
        keys = _neighbourhood(measure.encoded[i], threshold)
        if keys is None:
            wide.append(i)
        for key in keys or ():
            index[key].append(i)
    pairs = {(min(i, j), max(i, j)) for i in wide for j in members if i != j}
    for j in members:
        keys = _neighbourhood(measure.encoded[j], threshold)
        if keys is None:
            pairs |= {(min(i, j), max(i, j)) for i in asked if i != j}
            continue
        for key in keys:
            for i in index.get(key, ()):
                if i != j:
                    pairs.add((min(i, j), max(i, j)))
    return pairs


def _neighbourhood(encoded: str, threshold: float) -> set[str] | None:
    """The name (one character per segment) with up to k of its segments deleted, k the most edits
    a near name can be away; None when that set would be too large to be worth indexing."""
    edits = _max_edits(len(encoded), threshold)
    if edits is None or sum(math.comb(len(encoded), r) for r in range(edits + 1)) > _MAX_KEYS:
        return None
    level, keys = {encoded}, {encoded}
    for _ in range(edits):
        level = {key[:p] + key[p + 1:] for key in level for p in range(len(key))}
        keys |= level
    return keys


def _max_edits(length: int, threshold: float) -> int | None:
    """The most segment edits between a name of `length` segments and any name it is near: with d
    the difference in length, the cost is at least 1.5 d + (edits - d), below threshold times the
    mean length. None when no bound exists (a threshold of 3 or more)."""
    if threshold >= 2 * INDEL:
        return None
    most = 0
    other = 1
    while INDEL * max(0, other - length) < threshold * (length + other) / 2:
        gap = abs(other - length)
        budget = threshold * (length + other) / 2 - (INDEL - 1) * gap
        if INDEL * gap < threshold * (length + other) / 2:
            most = max(most, math.ceil(budget + 1e-9) - 1)
        other += 1
    return most


class _Measure:
    """Names as arrays of segment codes (and one character per segment, for the deletion keys)."""

    def __init__(self, names: list[str]) -> None:
        self.names = names
        vocabulary: dict[str, int] = {}
        codes = [[vocabulary.setdefault(seg, len(vocabulary)) for seg in segments(n)] for n in names]
        self.words = list(vocabulary)
        self.encoded = ["".join(chr(0x100 + c) for c in row) for row in codes]
        self.lengths = np.array([len(row) for row in codes], dtype=np.int64)
        width = max((len(row) for row in codes), default=0)
        self.codes = np.full((len(codes), width), -1, dtype=np.int64)
        for k, row in enumerate(codes):
            self.codes[k, : len(row)] = row

    def distances(self, first: np.ndarray, second: np.ndarray, limit: float | None = None) -> np.ndarray:
        """Normalised segment distances of the pairs (first[k], second[k]); with `limit`, values
        at or above it may come back as infinity."""
        result = np.zeros(len(first))
        la_all, lb_all = self.lengths[first], self.lengths[second]
        for la, lb in set(zip(la_all.tolist(), lb_all.tolist())):
            ks = np.nonzero((la_all == la) & (lb_all == lb))[0]
            budget = None if limit is None else limit * (la + lb) / 2
            left, right = self.codes[first[ks], :la], self.codes[second[ks], :lb]
            dist = _dl(left, right, self._costs(left[:, :, None], right[:, None, :]), budget)
            result[ks] = dist * 2 / (la + lb)
        return result

    def _costs(self, left: np.ndarray, right: np.ndarray) -> np.ndarray:
        """The character distance of every segment of `left` to every one of `right` (broadcast),
        measured once per distinct pair of words."""
        a, b = np.broadcast_arrays(left, right)
        flat = np.stack([a.ravel(), b.ravel()], axis=1)
        distinct, inverse = np.unique(flat, axis=0, return_inverse=True)
        costs = np.array([0.0 if x == y else DamerauLevenshtein.distance(self.words[x], self.words[y])
                          for x, y in distinct.tolist()], dtype=np.float32)
        return costs[inverse.reshape(-1)].reshape(a.shape)


def _dl(left: np.ndarray, right: np.ndarray, sub: np.ndarray, budget: float | None) -> np.ndarray:
    """Damerau-Levenshtein (optimal string alignment) over segment codes, vectorised over pairs,
    with `sub` the substitution cost of every two segments. With a budget, cells that only paths
    costing at least the budget can cross are skipped."""
    pairs, la, lb = left.shape[0], left.shape[1], right.shape[1]
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
