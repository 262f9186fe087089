"""The 500x500 turtlesim canvas: background fill, a transparent path layer, turtle sprites."""

from __future__ import annotations

import math
import threading

from PySide6.QtCore import QLineF, QPointF, QRectF, Qt
from PySide6.QtGui import QColor, QImage, QPainter, QPainterPath, QPen

from turtlesim_py.sim import CANVAS_PIXELS, PIXELS_PER_METER

# Cosmetic shell colours; each turtle gets one at random (upstream picks a random image).
SHELL_COLOURS = [
    (46, 139, 87), (34, 120, 60), (85, 107, 47), (0, 128, 128), (107, 142, 35),
    (60, 110, 160), (139, 90, 43), (120, 80, 150), (176, 120, 40), (70, 130, 80),
]


class Canvas:
    """Owns the path image. All access goes through `lock` (the window paints from Qt's thread)."""

    def __init__(self, lock: threading.RLock | None = None) -> None:
        self.lock = lock or threading.RLock()
        self.path = QImage(CANVAS_PIXELS, CANVAS_PIXELS, QImage.Format.Format_ARGB32)
        self._painter: QPainter | None = None
        self._pen = QPen()
        self._pen.setCapStyle(Qt.PenCapStyle.RoundCap)
        self._pen_key: tuple[int, int, int, int] | None = None
        self._pending: list[tuple[tuple[int, int, int, int], QLineF]] = []
        self.clear()

    def clear(self) -> None:
        with self.lock:
            self._pending.clear()
            self.end_drawing()
            self.path.fill(QColor(255, 255, 255, 0))

    def draw_line(self, x0: float, y0: float, x1: float, y1: float,
                  rgb: tuple[int, int, int], width: int) -> None:
        """A segment between two internal positions (metres, y downward).

        Segments are queued and drawn by flush() (the tick calls it once, and every reader
        of pixels first): a run of segments with the same pen is one drawLines call, which
        draws the same pixels as one drawLine per segment in the same order (checked by
        src/turtlesim/test/test_turtlesim_sim.py), at about half the cost per segment.
        """
        m = PIXELS_PER_METER
        self._pending.append(((*rgb, width), QLineF(x0 * m, y0 * m, x1 * m, y1 * m)))

    def flush(self) -> None:
        """Draw the queued segments, oldest first. The painter stays open from tick to tick
        (opening one and setting its pen every tick was a third of a tick's cost); whoever
        reads the whole image ends it first (end_drawing)."""
        pending = self._pending
        if not pending:
            return
        if self._painter is None:
            self._painter = QPainter(self.path)
        painter = self._painter
        run: list[QLineF] = []
        run_key = None
        for key, line in pending:
            if key != run_key:
                if run:
                    self._draw_run(painter, run_key, run)
                    run = []
                run_key = key
            run.append(line)
        self._draw_run(painter, run_key, run)
        pending.clear()

    def _draw_run(self, painter: QPainter, key: tuple[int, int, int, int],
                  lines: list[QLineF]) -> None:
        if key != self._pen_key:
            self._pen.setColor(QColor(key[0], key[1], key[2]))
            self._pen.setWidth(key[3])
            painter.setPen(self._pen)
            self._pen_key = key
        if len(lines) == 1:
            painter.drawLine(lines[0])
        else:
            painter.drawLines(lines)

    def end_drawing(self) -> None:
        self.flush()
        if self._painter is not None:
            self._painter.end()
            self._painter = None
            self._pen_key = None

    def rgb_at(self, px: int, py: int) -> tuple[int, int, int]:
        """RGB of the path layer (alpha ignored: untouched pixels read 255,255,255)."""
        self.flush()
        value = self.path.pixel(px, py)
        return (value >> 16) & 0xFF, (value >> 8) & 0xFF, value & 0xFF

    def composite(self, background: tuple[int, int, int],
                  turtles: list[tuple[float, float, float, tuple[int, int, int]]]) -> QImage:
        """Background, then paths, then a sprite per (x, y_int, theta, shell colour)."""
        with self.lock:
            self.end_drawing()
            image = QImage(CANVAS_PIXELS, CANVAS_PIXELS, QImage.Format.Format_RGB32)
            image.fill(QColor(*background))
            painter = QPainter(image)
            painter.drawImage(0, 0, self.path)
            painter.setRenderHint(QPainter.RenderHint.Antialiasing)
            for x, y_int, theta, shell in turtles:
                draw_turtle(painter, x * PIXELS_PER_METER, y_int * PIXELS_PER_METER, theta, shell)
            painter.end()
            return image


def draw_turtle(painter: QPainter, cx: float, cy: float, theta: float,
                shell: tuple[int, int, int]) -> None:
    """Our own turtle sprite (about 45 px long), head pointing along theta."""
    painter.save()
    painter.translate(cx, cy)
    painter.rotate(-math.degrees(theta))  # image y points down, theta is counter-clockwise
    skin = QColor(150, 200, 110)
    outline = QPen(QColor(30, 50, 20), 1.5)
    painter.setPen(outline)
    painter.setBrush(skin)
    for lx, ly in ((8, -11), (8, 11), (-9, -11), (-9, 11)):  # legs
        painter.drawEllipse(QRectF(lx - 4.5, ly - 3.5, 9, 7))
    tail = QPainterPath()
    tail.moveTo(-14, -2.5)
    tail.lineTo(-21, 0)
    tail.lineTo(-14, 2.5)
    tail.closeSubpath()
    painter.drawPath(tail)
    painter.drawEllipse(QRectF(13, -5, 10, 10))  # head
    painter.setBrush(QColor(*shell))
    painter.drawEllipse(QRectF(-15, -11, 30, 22))  # shell
    painter.setPen(QPen(QColor(*shell).darker(150), 1.2))
    painter.drawLine(QPointF(-9, 0), QPointF(9, 0))
    painter.drawLine(QPointF(0, -10), QPointF(0, 10))
    painter.setPen(Qt.PenStyle.NoPen)
    painter.setBrush(QColor(20, 20, 20))
    painter.drawEllipse(QPointF(19.5, -2.5), 1.3, 1.3)  # eyes
    painter.drawEllipse(QPointF(19.5, 2.5), 1.3, 1.3)
    painter.restore()
