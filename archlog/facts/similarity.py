"""Near-miss names: segment-aware Damerau-Levenshtein distance with a prefix-filtered join.

Names are split on '/' and '_' (an absolute name keeps its empty root segment). Substituting one
segment for another costs the character-level Damerau-Levenshtein distance of the two;
inserting or deleting a segment costs 1.5 and transposing two neighbours costs 1. The sum is
divided by the mean segment count. Two names are near misses when that is below the threshold
(default 0.5). The insertion cost makes replacing a whole segment (delete + insert) cost 3, as
much as three character edits, so /a/point and /a/line stay apart while /a/point and
/a/point_class, or /base_waypoint and /base_waypoints, are near.
"""

from __future__ import annotations

import math
import re
from collections import Counter, defaultdict
from collections.abc import Iterable

from rapidfuzz.distance import OSA, DamerauLevenshtein

_SPLIT = re.compile(r"[/_]")
INDEL = 1.5


def segments(name: str) -> list[str]:
    return _SPLIT.split(name)


def distance(a: str, b: str) -> float:
    """The normalised segment distance of two names."""
    sa, sb = segments(a), segments(b)
    return _segment_dl(sa, sb) / ((len(sa) + len(sb)) / 2)


def _segment_dl(a: list[str], b: list[str]) -> float:
    rows, cols = len(a) + 1, len(b) + 1
    d = [[0.0] * cols for _ in range(rows)]
    for i in range(rows):
        d[i][0] = i * INDEL
    for j in range(cols):
        d[0][j] = j * INDEL
    for i in range(1, rows):
        for j in range(1, cols):
            sub = 0.0 if a[i - 1] == b[j - 1] else DamerauLevenshtein.distance(a[i - 1], b[j - 1])
            d[i][j] = min(d[i - 1][j] + INDEL, d[i][j - 1] + INDEL, d[i - 1][j - 1] + sub)
            if i > 1 and j > 1 and a[i - 1] == b[j - 2] and a[i - 2] == b[j - 1]:
                d[i][j] = min(d[i][j], d[i - 2][j - 2] + 1)
    return d[-1][-1]


def near_pairs(names: Iterable[str], threshold: float = 0.5) -> list[tuple[str, str, float]]:
    """Every unordered pair of distinct names whose distance is below `threshold`.

    Two names can only be that close if they share more than (1 - threshold) of the segments of
    each, so candidates come from a prefix filter over segments ordered rarest first.
    """
    unique = sorted(set(names))
    tokens = [_tokens(n) for n in unique]
    split = [segments(n) for n in unique]
    frequency = Counter(t for ts in tokens for t in ts)
    index: dict[tuple[str, int], list[int]] = defaultdict(list)
    result = []
    for i, toks in enumerate(tokens):
        ordered = sorted(toks, key=lambda t: (frequency[t], t))
        need = math.floor((1 - threshold) * len(ordered)) + 1
        prefix = ordered[: max(len(ordered) - need + 1, 1)]
        candidates = {j for t in prefix for j in index[t]}
        for t in prefix:
            index[t].append(i)
        for j in candidates:
            budget = threshold * (len(tokens[j]) + len(toks)) / 2
            # every segment edit costs at least 1, so OSA over segments bounds the distance below
            if INDEL * abs(len(tokens[j]) - len(toks)) >= budget or OSA.distance(split[i], split[j]) >= budget:
                continue
            score = _segment_dl(split[j], split[i]) * 2 / (len(split[i]) + len(split[j]))
            if score < threshold:
                result.append((unique[j], unique[i], score))
    return sorted(result)


def _tokens(name: str) -> list[tuple[str, int]]:
    seen: Counter[str] = Counter()
    out = []
    for seg in segments(name):
        out.append((seg, seen[seg]))
        seen[seg] += 1
    return out
