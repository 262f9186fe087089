"""A frame's transforms to its parent over time (TimeCache) or for all time (StaticCache).

Entries are tuples (parent, x, y, z, qx, qy, qz, qw); stamps are int nanoseconds, kept in a
list sorted oldest first beside the entries, so a lookup is one bisect.
"""
import math
from bisect import bisect_left, bisect_right

from tf2_py.exceptions import EXTRAPOLATION_ERROR
from tf2_py.maths import slerp

Entry = tuple[str, float, float, float, float, float, float, float]


def display_time(nanoseconds: int) -> str:
    """A time as tf2 prints it in messages: seconds with six decimals."""
    return f'{nanoseconds / 1e9:.6f}'


class TimeCache:
    """Transforms of one frame within the last `max_age` nanoseconds of its newest stamp."""

    __slots__ = ('entries', 'max_age', 'stamps')
    is_static = False

    def __init__(self, max_age: int) -> None:
        self.max_age = max_age
        self.stamps: list[int] = []
        self.entries: list[Entry] = []

    def insert(self, stamp: int, entry: Entry) -> bool:
        """Store a sample; False when it is older than the cache keeps (tf2's TF_OLD_DATA)."""
        stamps = self.stamps
        if stamps:
            latest = stamps[-1]
            too_old = bisect_left(stamps, latest - self.max_age)
            if too_old:
                del stamps[:too_old]
                del self.entries[:too_old]
            if stamp < latest - self.max_age:
                return False
        at = bisect_right(stamps, stamp)
        same = at - 1
        while same >= 0 and stamps[same] == stamp:  # an exact repeat is stored once
            if self.entries[same] == entry:
                return True
            same -= 1
        stamps.insert(at, stamp)
        self.entries.insert(at, entry)
        return True

    def data_at(self, time: int) -> Entry | None:
        """The transform at `time` (0: the newest), interpolated between the samples around
        it; None when that would need extrapolation (explain() says why)."""
        stamps = self.stamps
        if not stamps:
            return None
        if time == 0:
            return self.entries[-1]
        if time >= stamps[-1]:
            return self.entries[-1] if time == stamps[-1] else None
        if time <= stamps[0]:
            return self.entries[0] if time == stamps[0] else None
        newer_at = bisect_right(stamps, time)
        older = self.entries[newer_at - 1]
        newer = self.entries[newer_at]
        older_stamp = stamps[newer_at - 1]
        if older_stamp == time or older[0] != newer[0]:  # no interpolation across a re-parent
            return older
        ratio = (time - older_stamp) / (stamps[newer_at] - older_stamp)
        keep = 1.0 - ratio
        qx, qy, qz, qw = slerp(older[4:], newer[4:], ratio)
        return (older[0], older[1] * keep + newer[1] * ratio, older[2] * keep + newer[2] * ratio,
                older[3] * keep + newer[3] * ratio, qx, qy, qz, qw)

    def explain(self, time: int) -> tuple[int, str]:
        """tf2's error code and message for a data_at(time) that returned None."""
        stamps = self.stamps
        if not stamps:
            return EXTRAPOLATION_ERROR, ''
        if len(stamps) == 1:
            return EXTRAPOLATION_ERROR, (
                f'Lookup would require extrapolation at time {display_time(time)}, '
                f'but only time {display_time(stamps[0])} is in the buffer')
        if time > stamps[-1]:
            return EXTRAPOLATION_ERROR, (
                'Lookup would require extrapolation into the future.  Requested time '
                f'{display_time(time)} but the latest data is at time {display_time(stamps[-1])}')
        return EXTRAPOLATION_ERROR, (
            'Lookup would require extrapolation into the past.  Requested time '
            f'{display_time(time)} but the earliest data is at time {display_time(stamps[0])}')

    def latest(self) -> tuple[int, str | None]:
        """(newest stamp, its parent), or (0, None) when empty."""
        if not self.stamps:
            return 0, None
        return self.stamps[-1], self.entries[-1][0]

    def latest_stamp(self) -> int:
        return self.stamps[-1] if self.stamps else 0

    def oldest_stamp(self) -> int:
        return self.stamps[0] if self.stamps else 0

    def __len__(self) -> int:
        return len(self.stamps)

    def clear(self) -> None:
        self.stamps.clear()
        self.entries.clear()


class StaticCache:
    """A frame's one transform, valid at every time (a /tf_static frame)."""

    __slots__ = ('entry',)
    is_static = True

    def __init__(self, entry: Entry) -> None:
        self.entry = entry

    def insert(self, stamp: int, entry: Entry) -> bool:
        self.entry = entry
        return True

    def data_at(self, time: int) -> Entry:
        return self.entry

    def explain(self, time: int) -> tuple[int, str]:  # never called: data_at always answers
        return EXTRAPOLATION_ERROR, ''

    def latest(self) -> tuple[int, str]:
        return 0, self.entry[0]

    def latest_stamp(self) -> int:
        return 0

    def oldest_stamp(self) -> int:
        return 0

    def __len__(self) -> int:
        return 1

    def clear(self) -> None:
        """Static frames survive clear(), as in tf2."""


def is_finite(entry: Entry) -> bool:
    return not any(math.isnan(value) for value in entry[1:])
