"""Walk the points of a straight line in fixed steps (upstream's `LineIterator`).

The walk steps along x (along y for a vertical line), clamped to the end point, and
rounds each coordinate to 5 decimals so that the points of y = 2x stay whole numbers.
"""

from __future__ import annotations

import math

Number = int | float


def _check_number(name: str, value: object) -> None:
    # bool is an int to Python, but never a coordinate.
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise TypeError(f'{name} must be a number (int or float)')


class LineIterator:
    """Iterates along the points of the line from (x0, y0) to (x1, y1)."""

    def __init__(self, x0: Number, y0: Number, x1: Number, y1: Number,
                 step_size: Number = 1.0) -> None:
        """
        Start at (x0, y0).

        Raises TypeError when a coordinate or step_size is no number, ValueError when
        step_size is not positive or the line has zero length.
        """
        for name, value in (('x0', x0), ('y0', y0), ('x1', x1), ('y1', y1),
                            ('step_size', step_size)):
            _check_number(name, value)
        if step_size <= 0:
            raise ValueError('step_size must be a positive number')
        if x0 == x1 and y0 == y1:
            raise ValueError('Line has zero length (All 4 points have same coordinates)')

        self.x0_ = x0
        self.y0_ = y0
        self.x1_ = x1
        self.y1_ = y1
        self.x_ = x0
        self.y_ = y0
        self.step_size_ = step_size
        self.valid_ = True
        if x1 != x0:  # y = m x + b; a vertical line steps along y instead
            self.m_ = (y1 - y0) / (x1 - x0)
            self.b_ = y1 - self.m_ * x1

    def isValid(self) -> bool:
        """Whether the current point is still on the line."""
        return self.valid_

    def advance(self) -> None:
        """Move one step towards the end point; past it the iterator becomes invalid."""
        if self.x1_ != self.x0_:
            forward = self.x1_ > self.x0_
            if (self.x_ < self.x1_) if forward else (self.x_ > self.x1_):
                step = self.step_size_ if forward else -self.step_size_
                low, high = sorted((self.x0_, self.x1_))
                self.x_ = round(self.clamp(self.x_ + step, low, high), 5)
                self.y_ = round(self.m_ * self.x_ + self.b_, 5)
            else:
                self.valid_ = False
            return
        forward = self.y1_ > self.y0_
        if (self.y_ < self.y1_) if forward else (self.y_ > self.y1_):
            step = self.step_size_ if forward else -self.step_size_
            low, high = sorted((self.y0_, self.y1_))
            self.y_ = round(self.clamp(self.y_ + step, low, high), 5)
        else:
            self.valid_ = False

    def getX(self) -> Number:
        """Abscissa of the current point."""
        return self.x_

    def getY(self) -> Number:
        """Ordinate of the current point."""
        return self.y_

    def getX0(self) -> Number:
        """Abscissa of the start point."""
        return self.x0_

    def getY0(self) -> Number:
        """Ordinate of the start point."""
        return self.y0_

    def getX1(self) -> Number:
        """Abscissa of the end point."""
        return self.x1_

    def getY1(self) -> Number:
        """Ordinate of the end point."""
        return self.y1_

    def get_line_length(self) -> float:
        """Length of the line."""
        return math.sqrt((self.x1_ - self.x0_) ** 2 + (self.y1_ - self.y0_) ** 2)

    def clamp(self, n: Number, min_n: Number, max_n: Number) -> Number:
        """N limited to [min_n, max_n]."""
        return min(max(n, min_n), max_n)
