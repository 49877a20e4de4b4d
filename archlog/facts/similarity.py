"""Near-miss names: segment-aware Damerau-Levenshtein distance, joined through segment deletions.

Names are split on '/' and '_' (an absolute name keeps its empty root segment). Substituting one
segment for another costs the character-level Damerau-Levenshtein distance of the two;
inserting or deleting a segment costs 1.5 and transposing two neighbours costs 1. The sum is
divided by the mean segment count. Two names are near misses when that is below the threshold
(default 0.5). The insertion cost makes replacing a whole segment (delete + insert) cost 3, as
much as three character edits, so /a/point and /a/line stay apart while /a/point and
/a/point_class, or /base_waypoint and /base_waypoints, are near.

Numbers tell instances apart: two names whose numbers (their digit runs, in order) differ are
never near, so /robot_3/scan is not a typo of /robot_4/scan, nor camera1 of camera2; and a segment
that is a number is never substituted (replacing it costs a deletion and an insertion, 3). One
exception: a name and the same name under more namespaces (/cmd_vel and /robot1/cmd_vel) are
measured as any other pair, since a missing or extra namespace is a misconfiguration, not
another instance.

Measuring costs the product of two names' segment counts (and of two segments' lengths), so names
past `MAX_SEGMENTS` segments or `MAX_CHARACTERS` characters (no ROS name comes near either) are not
compared: `too_long()` says which, and why.
"""

from __future__ import annotations

import itertools
import math
import re
from collections import defaultdict
from collections.abc import Iterable

import numpy as np
from rapidfuzz import process
from rapidfuzz.distance import DamerauLevenshtein

_SPLIT = re.compile(r"[/_]")
_NUMBER = re.compile(r"\d+")
INDEL = 1.5
MAX_SEGMENTS = 64
MAX_CHARACTERS = 1024
_MAX_KEYS = 512  # a name with more variants than this is measured against every name of its group
_SMALL_GROUP = 64  # groups up to this many names skip the vectorised filter of `_within_reach`
_MAX_WORD_EDITS = 4  # word replacements up to this character distance are enumerated; longer names are measured


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
    """The normalised segment distance of two names (infinite when their numbers differ, unless one
    is the other under more namespaces)."""
    if _NUMBER.findall(a) != _NUMBER.findall(b) and not (_tails(a) & {b} or _tails(b) & {a}):
        return math.inf
    return float(_Measure([a, b]).distances(np.array([0]), np.array([1]))[0])


def namespace_steps(a: str, b: str) -> int:
    """How many namespace levels above a's namespace the nearest namespace of a and b is (0 when
    they share their namespace): /robot_1/front/scan and /robot_1/rear/scan are 1 apart."""
    mine, theirs = a.split("/")[:-1], b.split("/")[:-1]
    shared = next((k for k, (x, y) in enumerate(zip(mine, theirs)) if x != y), min(len(mine), len(theirs)))
    return len(mine) - shared


def near_pairs(names: Iterable[str], threshold: float = 0.5) -> list[tuple[str, str, float]]:
    """Every unordered pair of distinct names whose distance is below `threshold` (names that are
    `too_long()` are left out)."""
    listed = list(names)
    return near_names(listed, listed, threshold)


def near_names(queries: Iterable[str], names: Iterable[str], threshold: float = 0.5) -> list[tuple[str, str, float]]:
    """Every unordered pair (a, b), a < b, of a name of `queries` and another name of `names` whose
    distance is below `threshold`, sorted; names that are `too_long()` are left out.

    Candidates meet on keys. An alignment of a query q with a name n substitutes, deletes and
    transposes segments of q and inserts segments of n; its cost is below the budget B that the
    threshold gives their lengths. So q's variants (each segment kept, deleted, swapped with its
    neighbour, or replaced by a word within that budget's character distance) include one equal
    to a variant of n with some of its segments deleted, and each side spends less than B on its
    variant. Only names that meet are measured, all at once. Names are grouped by their numbers
    first (names whose numbers differ are never near): copies of one name under many numbered
    namespaces never meet. A name with too many variants is measured against its whole group.
    A query also meets the same name under more or fewer namespaces, whatever their numbers.
    """
    asked = {q for q in queries if too_long(q) is None}
    given = {n for n in names if too_long(n) is None}
    if len(asked) > len(given):  # a pair is the same from either side: the smaller one enumerates variants
        asked, given = given, asked
    measure = _Measure(sorted(asked | given))
    groups: dict[tuple[str, ...], list[int]] = defaultdict(list)
    for index, name in enumerate(measure.names):
        groups[tuple(_NUMBER.findall(name))].append(index)
    budgets = {length: _budgets(length, threshold) for length in set(measure.lengths.tolist())}
    rows = [i for i, name in enumerate(measure.names) if name in asked]
    words = _Words(measure.words, np.unique(measure.codes[rows]).tolist(),
                   max((budgets[int(measure.lengths[i])][0] for i in rows), default=0.0))
    variants = _Variants(words)
    pairs: set[tuple[int, int]] = set()
    for members in groups.values():
        found = [i for i in members if measure.names[i] in asked]
        targets = [j for j in members if measure.names[j] in given]
        if found and targets:
            pairs |= _candidates(measure, targets, found, budgets, variants, threshold)
    pairs |= _namespaced(measure, asked, given)
    if not pairs:
        return []
    i, j = (np.array(column) for column in zip(*sorted(pairs)))
    scores = measure.distances(i, j, threshold)
    keep = scores < threshold
    return [(measure.names[a], measure.names[b], float(d)) for a, b, d in zip(i[keep], j[keep], scores[keep])]


def _tails(name: str) -> set[str]:
    """The name without one or more of its leading namespaces (/a/b/c: /b/c and /c)."""
    parts = name.split("/")
    return {"/" + "/".join(parts[k:]) for k in range(2, len(parts))} if name.startswith("/") else set()


def _namespaced(measure: _Measure, asked: set[str], given: set[str]) -> set[tuple[int, int]]:
    """Pairs (i < j) of a name of `asked` and the same name of `given` under more or fewer namespaces."""
    position = {name: index for index, name in enumerate(measure.names)}
    under: dict[str, list[int]] = defaultdict(list)
    lasts = {name.rpartition("/")[2] for name in asked}
    for name in given:
        if name.rpartition("/")[2] in lasts:  # the same name under more namespaces ends as it does
            for tail in _tails(name):
                under[tail].append(position[name])
    pairs = set()
    for name in asked:
        i = position[name]
        for j in [*under.get(name, ()), *(position[t] for t in _tails(name) if t in given)]:
            pairs.add((min(i, j), max(i, j)))
    return pairs


class _Wide(Exception):
    """A name with more variants than are worth indexing."""


class _Words:
    """The words (segments) within a character distance below `budget` of each of the words `rows`
    (codes: the queries' words). Two words with different numbers in both (3 and 7, robot3 and
    robot7) are not near: swapping one number for another changes the name's numbers, and names
    whose numbers differ are never near. A number is near no word (substituting it costs as much as
    deleting it and inserting the other)."""

    def __init__(self, words: list[str], rows: list[int], budget: float) -> None:
        self.budget = min(budget, _MAX_WORD_EDITS + 1)
        self.number = [word.isdigit() for word in words]
        self.near: dict[int, list[tuple[int, float]]] = defaultdict(list)
        cutoff = max(0, math.ceil(self.budget) - 1)
        numbers = [tuple(_NUMBER.findall(word)) for word in words]
        columns: dict[tuple[str, ...], list[int]] = defaultdict(list)  # words by their numbers (none: ())
        for k in range(len(words)):
            if not self.number[k]:
                columns[numbers[k]].append(k)
        plain = columns.get((), [])
        every = sorted(k for members in columns.values() for k in members)
        asked: dict[tuple[str, ...], list[int]] = defaultdict(list)
        for row in rows:
            if cutoff and not self.number[row]:
                asked[numbers[row]].append(row)
        # a query is compared with the words of its numbers and those without any (a word without
        # numbers with every word): with many numbered words (one per instance) this is linear
        # where comparing all of them is quadratic
        for key, members in asked.items():
            self._compare(words, members, every if key == () else sorted(columns[key] + plain), cutoff)
        for found in self.near.values():
            found.sort()

    def _compare(self, words: list[str], rows: list[int], columns: list[int], cutoff: int) -> None:
        """Record the words of `columns` within `cutoff` of each word of `rows` (a few at a time
        directly, many in blocks)."""
        if len(rows) * len(columns) < 256:
            for a in rows:
                for b in columns:
                    if a != b and (found := DamerauLevenshtein.distance(words[a], words[b], score_cutoff=cutoff)) <= cutoff:
                        self.near[a].append((b, float(found)))
            return
        targets = [words[b] for b in columns]
        for start in range(0, len(rows), 1024):
            block = process.cdist([words[a] for a in rows[start:start + 1024]], targets,
                                  scorer=DamerauLevenshtein.distance, score_cutoff=cutoff, dtype=np.int32,
                                  workers=-1)
            for a, b in zip(*np.nonzero(block <= cutoff)):
                if rows[start + a] != columns[b]:
                    self.near[rows[start + a]].append((columns[b], float(block[a, b])))


def _candidates(measure: _Measure, members: list[int], asked: list[int], budgets: dict[int, tuple[float, float]],
                variants: _Variants, threshold: float) -> set[tuple[int, int]]:
    """Pairs (i < j) of a name of `asked` and another of `members` whose variants meet at a cost
    (both sides' edits) below what the threshold allows their lengths."""
    index: dict[str, list[tuple[int, float]]] = defaultdict(list)
    lengths = measure.counts
    pairs: set[tuple[int, int]] = set()
    for i in asked:
        try:
            found = variants.of(measure.codes[i, : measure.lengths[i]].tolist(), budgets[int(measure.lengths[i])][0])
        except _Wide:
            pairs |= {(min(i, j), max(i, j)) for j in members if i != j}
            continue
        for key, spent in found.items():
            index[key].append((i, spent))
    for entries in index.values():
        entries.sort(key=lambda entry: entry[1])
    longest = max(lengths[i] for i in asked)
    for j in _within_reach(measure, members, index, budgets):
        keys = _deletions(measure.encoded(j), budgets[int(measure.lengths[j])][1])
        if keys is None:
            pairs |= {(min(i, j), max(i, j)) for i in asked if i != j}
            continue
        cap = threshold * (longest + lengths[j]) / 2
        for key, deleted in keys.items():
            for i, spent in index.get(key, ()):
                if spent + deleted >= cap:
                    break
                if i != j and spent + deleted < threshold * (lengths[i] + lengths[j]) / 2:
                    pairs.add((min(i, j), max(i, j)))
    return pairs


class _Variants:
    """Queries' variants, enumerated once per shape: the numbers of a name (which are never
    substituted) are placeholders, so /robot_1/scan and /robot_2/scan share one enumeration."""

    def __init__(self, words: _Words) -> None:
        self.words = words
        self.shapes: dict[tuple[tuple[int, ...], float], dict[str, float] | None] = {}

    def of(self, codes: list[int], budget: float) -> dict[str, float]:
        numbers = [code for code in codes if self.words.number[code]]
        placeholders = iter(range(-1, -len(numbers) - 1, -1))
        shape = tuple(next(placeholders) if self.words.number[code] else code for code in codes)
        if (shape, budget) not in self.shapes:
            try:
                self.shapes[shape, budget] = _variants(list(shape), budget, self.words)
            except _Wide:
                self.shapes[shape, budget] = None
        found = self.shapes[shape, budget]
        if found is None:
            raise _Wide
        if not numbers:
            return found
        table = {k: chr(0x100 + code) for k, code in enumerate(numbers, 1)}
        return {key.translate(table): spent for key, spent in found.items()}


def _variants(codes: list[int], budget: float, words: _Words) -> dict[str, float]:
    """A query's variants (one character per segment; a negative code -k is the k-th number's
    placeholder, character k) of cost below `budget`, each with its least cost: segments kept,
    deleted (1.5), swapped with a different neighbour (1), or replaced by a near word."""
    if budget > words.budget:
        raise _Wide
    found: dict[str, float] = {}
    steps = [0]

    def walk(at: int, spent: float, prefix: str) -> None:
        steps[0] += 1
        if steps[0] > 16 * _MAX_KEYS:
            raise _Wide
        if at == len(codes):
            found[prefix] = min(spent, found.get(prefix, spent))
            return
        here = codes[at]
        walk(at + 1, spent, prefix + _char(here))
        if spent + INDEL < budget:
            walk(at + 1, spent + INDEL, prefix)
        for other, cost in words.near.get(here, ()):
            if spent + cost < budget:
                walk(at + 1, spent + cost, prefix + _char(other))
        if at + 1 < len(codes) and codes[at + 1] != here and spent + 1 < budget:
            walk(at + 2, spent + 1, prefix + _char(codes[at + 1]) + _char(here))

    walk(0, 0.0, "")
    return found


def _char(code: int) -> str:
    """A segment code as one character (a number's placeholder -k as character k)."""
    return chr(0x100 + code) if code >= 0 else chr(-code)


def _within_reach(measure: _Measure, members: list[int], index: dict[str, list[tuple[int, float]]],
                  budgets: dict[int, tuple[float, float]]) -> list[int]:
    """The members that can meet a query's variant in `index`: a member's deletion key keeps all
    but `_most_deleted` of its segments, and each segment a key keeps is a word of some variant
    (members with too many deletion keys to index are kept). A small group (one per numbered
    instance) is kept whole: filtering it costs more than looking its few keys up."""
    if len(members) <= _SMALL_GROUP:
        return members
    words = np.array(sorted({ord(ch) - 0x100 for key in index for ch in key}), dtype=np.int64)
    rows = np.array(members, dtype=np.int64)
    lengths = measure.lengths[rows]
    need = np.zeros(int(lengths.max()) + 1, dtype=np.int64)
    for length in set(lengths.tolist()):
        most = _most_deleted(length, budgets[length][1])
        need[length] = 0 if most is None else length - most
    shared = np.isin(measure.codes[rows], words).sum(axis=1)
    return rows[shared >= need[lengths]].tolist()


def _most_deleted(length: int, budget: float) -> int | None:
    """How many segments a name of `length` segments may lose to deletions (1.5 each) below
    `budget`; None when its deletion keys would be too many to be worth indexing."""
    most = min(max(0, math.ceil(budget / INDEL) - 1), length)
    return None if sum(math.comb(length, r) for r in range(most + 1)) > _MAX_KEYS else most


def _deletions(encoded: str, budget: float) -> dict[str, float] | None:
    """The name (one character per segment) with segments deleted at 1.5 each, below `budget`,
    each with its cost; None when that set would be too large to be worth indexing."""
    most = _most_deleted(len(encoded), budget)
    if most is None:
        return None
    level, keys = {encoded}, {encoded: 0.0}
    for count in range(1, most + 1):
        level = {key[:p] + key[p + 1:] for key in level for p in range(len(key))}
        for key in level:
            keys.setdefault(key, count * INDEL)
    return keys


def _budgets(length: int, threshold: float) -> tuple[float, float]:
    """For a name of `length` segments: the most a query may spend on its own edits, and the most
    a name may spend on deletions, in an alignment cheaper than the threshold allows. The cost of
    two names of lengths l and m is below threshold * (l + m) / 2 and at least 1.5 |l - m|."""
    if threshold >= 2 * INDEL:
        return math.inf, math.inf
    query = deleted = 0.0
    other = 1
    while INDEL * (other - length) < threshold * (length + other) / 2:
        limit = threshold * (length + other) / 2
        if INDEL * abs(other - length) < limit:
            query = max(query, limit - INDEL * max(0, other - length))
            deleted = max(deleted, limit)
        other += 1
    return query, deleted


class _Measure:
    """Names as arrays of segment codes (and one character per segment, for the deletion keys)."""

    def __init__(self, names: list[str]) -> None:
        self.names = names
        split = [segments(n) for n in names]
        self.words = list(dict.fromkeys(itertools.chain.from_iterable(split)))
        vocabulary = {word: code for code, word in enumerate(self.words)}
        flat = np.fromiter((vocabulary[seg] for row in split for seg in row), dtype=np.int64)
        self.lengths = np.fromiter(map(len, split), dtype=np.int64, count=len(split))
        self.counts: list[int] = self.lengths.tolist()  # the same as Python ints, for lookups one at a time
        self.codes = np.full((len(names), int(self.lengths.max(initial=0))), -1, dtype=np.int64)
        starts = np.repeat(np.cumsum(self.lengths) - self.lengths, self.lengths)
        self.codes[np.repeat(np.arange(len(names)), self.lengths), np.arange(len(flat)) - starts] = flat

    def encoded(self, index: int) -> str:
        """A name as one character per segment."""
        return "".join(chr(0x100 + code) for code in self.codes[index, : self.lengths[index]].tolist())

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
        flat = a.ravel() * len(self.words) + b.ravel()
        distinct, inverse = np.unique(flat, return_inverse=True)
        costs = np.array([0.0 if x == y else 2 * INDEL if self.words[x].isdigit() or self.words[y].isdigit()
                          else DamerauLevenshtein.distance(self.words[x], self.words[y])
                          for x, y in zip(*np.divmod(distinct, len(self.words)))], dtype=np.float32)
        return costs[inverse].reshape(a.shape)


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
