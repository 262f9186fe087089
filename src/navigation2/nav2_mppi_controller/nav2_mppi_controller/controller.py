"""nav2_mppi_controller::MPPIController: the controller_server plugin around the optimizer.

Parameters are upstream's, under the plugin's name (`FollowPath.batch_size`,
`FollowPath.critics`, `FollowPath.CostCritic.cost_weight`, ...). Without `batch_size` the
batch is DEFAULT_BATCH_SIZE (what numpy runs well inside a 20 Hz cycle on 2 cores; README).
"""

from __future__ import annotations

from typing import Any

import numpy as np
from nav2_controller.exceptions import ControllerException, NoValidControl
from nav2_controller.geometry import Pose2D
from nav2_controller.plugins import PluginContext
from rclpy.parameter import Parameter

from nav2_mppi_controller.critics import CRITICS, CriticData, Grid
from nav2_mppi_controller.optimizer import Optimizer, read_settings
from nav2_mppi_controller.path_handler import PathHandler

DEFAULT_BATCH_SIZE = 1000
# Parameters of upstream's that this controller reads and does not use (no visualisation,
# no Ackermann model): declared so that a Nav2 params file gives no unknown-parameter lines.
UNUSED = {'TrajectoryVisualizer.trajectory_step': 5, 'TrajectoryVisualizer.time_step': 3,
          'AckermannConstraints.min_turning_r': 0.2, 'open_loop': False,
          'enforce_path_inversion': False, 'transform_tolerance': 0.1}


class MPPIController:
    def __init__(self, context: PluginContext) -> None:
        self.name = context.name
        self.node = context.node
        self.costmap_ros = context.costmap_ros
        self.log = context.node.get_logger()
        param = context.param
        self.visualize = bool(param('visualize', False))
        frequency = self.node.get_parameter('controller_frequency').value
        try:
            self.settings = read_settings(param, DEFAULT_BATCH_SIZE, frequency,
                                          self.log.warning)
        except ValueError as error:
            raise ControllerException(str(error)) from None
        if self.settings.shift_control_sequence:
            self.log.info('Controller period is equal to model dt. Control sequence '
                          'shifting is ON')
        self.critics = []
        for critic in param('critics', Parameter.Type.STRING_ARRAY) or []:
            cls = CRITICS.get(critic.split('::')[-1])
            if cls is None:
                raise ControllerException(
                    f'Critic {critic} is not available: the critics available are '
                    f"{', '.join(sorted(CRITICS))}")
            try:
                made = cls(critic, lambda key, default, c=critic: param(f'{c}.{key}', default),
                           param)
            except ValueError as error:
                raise ControllerException(str(error)) from None
            if getattr(made, 'warning', ''):
                self.log.warning(made.warning)
            self.critics.append(made)
            self.log.info(f'Critic loaded : mppi::critics::{cls.__name__}')
        costmap = self.costmap_ros.costmap
        half_size = max(costmap.size_x, costmap.size_y) * costmap.resolution * 0.5
        self.path_handler = PathHandler(
            float(param('max_robot_pose_search_dist', half_size)),
            float(param('prune_distance', 1.5)))
        for key, default in UNUSED.items():
            param(key, default)
        self.optimizer = Optimizer(self.settings)
        self.log.info('Optimizer reset')
        self.log.info(f'Configured MPPI Controller: {self.name}')

    def activate(self) -> None:
        self.log.info(f'Activated MPPI Controller: {self.name}')

    def deactivate(self) -> None:
        self.log.info(f'Deactivated MPPI Controller: {self.name}')

    def cleanup(self) -> None:
        self.log.info(f'Cleaned up MPPI Controller: {self.name}')

    def reset(self) -> None:
        self.optimizer.reset()

    def cancel(self) -> bool:
        return True

    def set_plan(self, path: np.ndarray) -> None:
        self.path_handler.set_path(path)

    def set_speed_limit(self, speed_limit: float, percentage: bool) -> None:
        self.optimizer.set_speed_limit(speed_limit, percentage)

    def _grid(self) -> tuple[Grid, tuple[float, float, float, float]]:
        with self.costmap_ros.lock:
            c = self.costmap_ros.costmap
            grid = Grid(c.costmap.copy(), c.origin_x, c.origin_y, c.resolution,
                        self.costmap_ros.config.layered.track_unknown)
        bounds = (c.origin_x, c.origin_y, c.origin_x + c.size_x * c.resolution,
                  c.origin_y + c.size_y * c.resolution)
        return grid, bounds

    def compute_velocity_commands(self, pose: Pose2D, speed: Pose2D, goal_checker: Any,
                                  plan_to_costmap: Pose2D) -> Pose2D:
        goal = self.path_handler.goal(plan_to_costmap)
        grid, bounds = self._grid()
        path = self.path_handler.transform_path(pose, plan_to_costmap, bounds)
        optimizer = self.optimizer
        attempts = 0
        while True:
            failed = False
            for _ in range(self.settings.iteration_count):
                failed = self._iterate(pose, speed, path, goal, grid)
            if not failed:
                break
            optimizer.reset()  # fallback: start again from a zero sequence
            attempts += 1
            if attempts > self.settings.retry_attempt_limit:
                raise NoValidControl('Optimizer fail to compute path')
        optimizer.smooth()
        command = optimizer.command()
        if self.settings.shift_control_sequence:
            optimizer.shift()
        return command

    def _iterate(self, pose: Pose2D, speed: Pose2D, path: np.ndarray, goal: Pose2D,
                 grid: Grid) -> bool:
        optimizer = self.optimizer
        x, y, yaws = optimizer.rollout(pose, speed)
        data = CriticData(pose=pose, vx=optimizer.v[0], wz=optimizer.v[2], x=x, y=y, yaws=yaws,
                          path=path, goal=goal, model_dt=self.settings.model_dt, grid=grid,
                          costs=np.zeros(self.settings.batch_size, dtype=np.float32))
        for critic in self.critics:
            critic.score(data)
        optimizer.update(data.costs)
        return data.fail_flag
