"""Burger mode: frames of a few burgers drifting over a black background and bouncing off
its edges, drawn with numpy (no camera, no OpenCV)."""

from __future__ import annotations

import random

import numpy as np

BURGER_WIDTH, BURGER_HEIGHT = 48, 36
COUNT = 5


def _sprite() -> tuple[np.ndarray, np.ndarray]:
    """One burger (BGR pixels and the mask of where it is), layer by layer from the top."""
    h, w = BURGER_HEIGHT, BURGER_WIDTH
    y, x = np.mgrid[0:h, 0:w]
    u = (x - (w - 1) / 2) / (w / 2)  # -1 .. 1 across
    pixels = np.zeros((h, w, 3), dtype=np.uint8)
    mask = np.zeros((h, w), dtype=bool)
    # (top row, bottom row, BGR colour, how round the ends are)
    layers = [(0, 13, (40, 140, 215), 'dome'), (13, 17, (40, 190, 60), 'flat'),
              (17, 22, (20, 200, 240), 'flat'), (22, 28, (30, 55, 95), 'flat'),
              (28, 36, (40, 140, 215), 'round')]
    for top, bottom, colour, shape in layers:
        v = (y - top) / max(1, bottom - top)  # 0 .. 1 down the layer
        if shape == 'dome':  # a half ellipse: the top bun
            inside = (u ** 2 + (1 - v) ** 2 <= 1.0) & (y >= top) & (y < bottom)
        elif shape == 'round':
            inside = (u ** 2 + v ** 2 <= 1.0) & (y >= top) & (y < bottom)
        else:
            inside = (np.abs(u) <= 0.97) & (y >= top) & (y < bottom)
        pixels[inside] = colour
        mask |= inside
    # sesame seeds on the bun
    for sx, sy in ((14, 5), (24, 3), (33, 6), (19, 9), (29, 9)):
        pixels[sy:sy + 2, sx:sx + 3] = (200, 235, 245)
    return pixels, mask


class Burger:
    """Renders frames of COUNT burgers that move a little at each frame."""

    def __init__(self) -> None:
        self._pixels, self._mask = _sprite()
        self._rng = random.Random()
        self._burgers: list[list[float]] = []
        self._size = (0, 0)

    def render_burger(self, width: int, height: int) -> np.ndarray:
        """A height x width x 3 BGR frame; ValueError when a burger does not fit."""
        if width < BURGER_WIDTH or height < BURGER_HEIGHT:
            raise ValueError(f'Target resolution must be at least the burger size '
                             f'({BURGER_WIDTH} x {BURGER_HEIGHT})')
        if self._size != (width, height):
            self._size = (width, height)
            self._burgers = [[self._rng.uniform(0, width - BURGER_WIDTH),
                              self._rng.uniform(0, height - BURGER_HEIGHT),
                              self._rng.choice((-3, -2, 2, 3)), self._rng.choice((-2, -1, 1, 2))]
                             for _ in range(COUNT)]
        frame = np.zeros((height, width, 3), dtype=np.uint8)
        for burger in self._burgers:
            x, y, dx, dy = burger
            if not 0 <= x + dx <= width - BURGER_WIDTH:
                dx = -dx
            if not 0 <= y + dy <= height - BURGER_HEIGHT:
                dy = -dy
            burger[:] = [x + dx, y + dy, dx, dy]
            top, left = int(burger[1]), int(burger[0])
            region = frame[top:top + BURGER_HEIGHT, left:left + BURGER_WIDTH]
            region[self._mask] = self._pixels[self._mask]
        return frame
