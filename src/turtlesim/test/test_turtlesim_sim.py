"""turtlesim's simulation maths as plain functions (no ROS, no Qt)."""

import math

import pytest
from turtlesim_py import sim

H = sim.CANVAS_HEIGHT


def test_canvas_size_is_upstreams_float32():
    assert sim.CANVAS_WIDTH == 11.088889122009277
    assert sim.CENTER == 5.544444561004639


@pytest.mark.parametrize('angle, expected', [
    (0.0, 0.0),
    (math.pi / 2, math.pi / 2),
    (3.5, 3.5 - 2 * sim.UPSTREAM_PI),
    (-3.5, -3.5 + 2 * sim.UPSTREAM_PI),
    (7.0, 7.0 - 2 * sim.UPSTREAM_PI),
    (-sim.UPSTREAM_PI, -sim.UPSTREAM_PI),
    (sim.UPSTREAM_PI, -sim.UPSTREAM_PI),  # [-pi, pi): +pi wraps to -pi
])
def test_norm_angle(angle, expected):
    assert sim.norm_angle(angle) == pytest.approx(expected, abs=1e-12)


def test_integrate_uses_the_updated_heading():
    x, y_int, theta = sim.integrate(1.0, 5.0, 0.0, vx=1.0, vy=0.0, w=math.pi / 2, dt=1.0)
    assert theta == pytest.approx(math.pi / 2)
    assert x == pytest.approx(1.0, abs=1e-7)
    assert y_int == pytest.approx(4.0)  # world y went up by 1, internal y down


def test_integrate_holonomic_sideways():
    x, y_int, theta = sim.integrate(2.0, 5.0, 0.0, vx=0.0, vy=1.0, w=0.0, dt=0.5)
    assert (x, y_int, theta) == pytest.approx((2.0, 4.5, 0.0))


def test_integrate_straight_line_at_fixed_step():
    x, y_int, theta = 1.0, 5.0, 0.0
    for _ in range(125):
        x, y_int, theta = sim.integrate(x, y_int, theta, 2.0, 0.0, 0.0, sim.FIXED_DT)
    assert x == pytest.approx(5.0)
    assert y_int == 5.0


@pytest.mark.parametrize('x, y_int, hit, clamped', [
    (5.0, 5.0, False, (5.0, 5.0)),
    (0.0, H, False, (0.0, H)),  # exactly on the wall is inside (strict comparisons)
    (-0.1, 5.0, True, (0.0, 5.0)),
    (12.0, 5.0, True, (sim.CANVAS_WIDTH, 5.0)),
    (5.0, -1.0, True, (5.0, 0.0)),
    (5.0, 20.0, True, (5.0, H)),
])
def test_wall_clamp(x, y_int, hit, clamped):
    assert sim.hits_wall(x, y_int) is hit
    assert sim.clamp_to_walls(x, y_int) == clamped


def test_wall_warning_text_uses_internal_y():
    assert sim.wall_warning(11.2, -0.0625) == (
        'Oh no! I hit the wall! (Clamping from [x=11.200000, y=-0.062500])')


def test_teleport_relative_rotates_then_moves():
    x, y_int, theta = sim.teleport_relative(5.0, 5.0, 0.0, linear=2.0, angular=math.pi / 2)
    assert (x, y_int, theta) == pytest.approx((5.0, 3.0, math.pi / 2))


def test_teleport_relative_does_not_normalise():
    assert sim.teleport_relative(5.0, 5.0, 3.0, 0.0, 3.0)[2] == 6.0


def test_teleport_absolute_clamps_only_above_the_top():
    assert sim.teleport_absolute(1.0, 2.0, 0.5) == (1.0, H - 2.0, 0.5)
    assert sim.teleport_absolute(1.0, 50.0, 0.0)[1] == 0.0
    assert sim.teleport_absolute(1.0, -3.0, 0.0)[1] == H + 3.0  # clamped later, with warning


def test_to_pixel_rounds_and_stays_inside():
    assert sim.to_pixel(sim.CENTER, sim.CENTER) == (250, 250)
    assert sim.to_pixel(sim.CANVAS_WIDTH, 0.0) == (499, 0)
    assert sim.to_pixel(2.0, 3.0) == (90, 135)


def test_rotate_step_turns_towards_the_goal_both_ways():
    step = sim.rotate_step(0.0, 1.0, 0.0)
    assert not step.done
    assert step.angular_velocity == 1.0
    assert step.remaining == pytest.approx(1.0)
    assert sim.rotate_step(0.0, -1.0, 0.0).angular_velocity == -1.0
    # the short way round across +-pi
    assert sim.rotate_step(3.0, -3.0, 3.0).angular_velocity == 1.0


def test_rotate_step_completes_within_tolerance_and_reports_start_minus_current():
    step = sim.rotate_step(0.99, 1.0, 0.0)
    assert step.done
    assert step.angular_velocity == 0.0
    assert step.delta == pytest.approx(-0.99)
    assert not sim.rotate_step(0.97, 1.0, 0.0).done


def test_rotate_step_full_turn_goal_is_already_reached():
    step = sim.rotate_step(0.0, 2 * sim.UPSTREAM_PI, 0.0)
    assert step.done and step.remaining == pytest.approx(0.0, abs=1e-9)


def test_pose_linear_velocity_is_a_magnitude():
    assert sim.pose_linear_velocity(-2.0, 0.0) == 2.0
    assert sim.pose_linear_velocity(3.0, 4.0) == 5.0


@pytest.mark.parametrize('value, ok', [
    (1.0, True), (-1e30, True), (math.nan, False), (math.inf, False), (-math.inf, False),
    (1e39, False),
])
def test_finite_float32(value, ok):
    assert sim.finite_float32(value) is ok


def test_window_shows_the_composited_canvas():
    import os

    os.environ.setdefault('QT_QPA_PLATFORM', 'offscreen')
    from PySide6.QtWidgets import QApplication
    from turtlesim_py.canvas import Canvas
    from turtlesim_py.window import CanvasWindow

    app = QApplication.instance() or QApplication([])
    canvas = Canvas()
    canvas.draw_line(1.0, 1.0, 5.0, 1.0, (255, 0, 0), 3)
    canvas.end_drawing()

    class Frame:
        def composite(self):
            return canvas.composite((10, 20, 30), [(8.0, 8.0, 0.0, (0, 128, 0))])

    window = CanvasWindow(Frame())
    assert window.windowTitle() == 'TurtleSim'
    assert (window.width(), window.height()) == (500, 500)
    image = window.grab().toImage()
    app.processEvents()
    assert image.pixelColor(135, 45).getRgb()[:3] == (255, 0, 0)
    assert image.pixelColor(400, 100).getRgb()[:3] == (10, 20, 30)
    assert image.pixelColor(360, 360).getRgb()[:3] != (10, 20, 30)  # the sprite


def test_queued_segments_draw_the_pixels_of_one_drawline_each():
    """Canvas.draw_line queues; flush() draws runs of one pen with drawLines. The image must
    equal drawing every segment on its own, in order, with upstream's pen (round caps)."""
    import os
    import random

    os.environ.setdefault('QT_QPA_PLATFORM', 'offscreen')
    from PySide6.QtCore import QPointF, Qt
    from PySide6.QtGui import QColor, QGuiApplication, QImage, QPainter, QPen
    from turtlesim_py.canvas import Canvas

    QGuiApplication.instance() or QGuiApplication([])
    rng = random.Random(24)
    pens = [((255, 0, 0), 3), ((0, 255, 0), 1), ((179, 184, 255), 7)]
    segments = []
    for _ in range(600):  # runs of one pen, then another, overlapping each other
        rgb, width = pens[rng.randrange(3)] if rng.random() < 0.2 else (
            segments[-1][4:] if segments else pens[0])
        x, y = rng.uniform(-0.5, 11.5), rng.uniform(-0.5, 11.5)
        segments.append((x, y, x + rng.uniform(-0.3, 0.3), y + rng.uniform(-0.3, 0.3),
                         rgb, width))
    canvas = Canvas()
    for index, segment in enumerate(segments):
        canvas.draw_line(*segment)
        if index % 97 == 0:
            canvas.rgb_at(0, 0)  # a colour read mid-tick draws what is queued
    canvas.end_drawing()

    expected = QImage(500, 500, QImage.Format.Format_ARGB32)
    expected.fill(QColor(255, 255, 255, 0))
    painter = QPainter(expected)
    for x0, y0, x1, y1, rgb, width in segments:
        pen = QPen(QColor(*rgb))
        pen.setWidth(width)
        pen.setCapStyle(Qt.PenCapStyle.RoundCap)
        painter.setPen(pen)
        painter.drawLine(QPointF(x0 * 45.0, y0 * 45.0), QPointF(x1 * 45.0, y1 * 45.0))
    painter.end()
    assert canvas.path == expected
