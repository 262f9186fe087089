"""The TurtleSim window: shows the composited canvas."""

from __future__ import annotations

from PySide6.QtGui import QPainter
from PySide6.QtWidgets import QWidget

from turtlesim_py.sim import CANVAS_PIXELS


class CanvasWindow(QWidget):
    def __init__(self, frame) -> None:
        super().__init__()
        self.frame = frame
        self.setWindowTitle('TurtleSim')
        self.setFixedSize(CANVAS_PIXELS, CANVAS_PIXELS)

    def paintEvent(self, event) -> None:
        image = self.frame.composite()
        painter = QPainter(self)
        painter.drawImage(0, 0, image)
        painter.end()

