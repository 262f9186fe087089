"""nav2_regulated_pure_pursuit_controller::RegulatedPurePursuitController, the plugin.

Parameters are upstream's under the plugin's name (`FollowPath.desired_linear_vel`, ...).
Each cycle: the plan near the robot in the robot's frame (path pruning as upstream's
PathHandler), the carrot at the lookahead distance, rotate to the path or to the goal
heading, else the pure pursuit curvature with the linear speed regulated by curvature,
cost and approach; then the arc up to the carrot is checked for collisions.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from geometry_msgs.msg import PointStamped
from nav2_controller.exceptions import ControllerException, InvalidPath, NoValidControl
from nav2_controller.geometry import (
    Pose2D,
    closest_index,
    compose,
    first_after_integrated_distance,
    to_frame,
)
from nav2_controller.plugins import PluginContext
from nav2_costmap_2d.cost_values import LETHAL_OBSTACLE, NO_INFORMATION
from nav2_costmap_2d.footprint import transform_footprint
from std_msgs.msg import Bool

from nav2_regulated_pure_pursuit_controller import regulation as reg

TYPE = 'regulated_pure_pursuit_controller::RegulatedPurePursuitController'
PARAMETERS = {
    'desired_linear_vel': 0.5, 'lookahead_dist': 0.6, 'min_lookahead_dist': 0.3,
    'max_lookahead_dist': 0.9, 'lookahead_time': 1.5, 'rotate_to_heading_angular_vel': 1.8,
    'transform_tolerance': 0.1, 'use_velocity_scaled_lookahead_dist': False,
    'min_approach_linear_velocity': 0.05, 'approach_velocity_scaling_dist': 0.6,
    'max_allowed_time_to_collision_up_to_carrot': 1.0,
    'use_regulated_linear_velocity_scaling': True,
    'use_cost_regulated_linear_velocity_scaling': True, 'cost_scaling_dist': 0.6,
    'cost_scaling_gain': 1.0, 'inflation_cost_scaling_factor': 3.0,
    'regulated_linear_scaling_min_radius': 0.90, 'regulated_linear_scaling_min_speed': 0.25,
    'use_fixed_curvature_lookahead': False, 'curvature_lookahead_dist': 0.6,
    'use_rotate_to_heading': True, 'rotate_to_heading_min_angle': 0.785,
    'max_angular_accel': 3.2, 'use_cancel_deceleration': False, 'cancel_deceleration': 3.2,
    'allow_reversing': False, 'interpolate_curvature_after_goal': False,
    'use_collision_detection': True, 'stateful': True}


class RegulatedPurePursuitController:
    def __init__(self, context: PluginContext) -> None:
        self.name = context.name
        self.node = context.node
        self.costmap_ros = context.costmap_ros
        self.log = context.node.get_logger()
        p = {key: context.param(key, default) for key, default in PARAMETERS.items()}
        costmap = self.costmap_ros.costmap
        size_x = costmap.size_x * costmap.resolution
        p['max_robot_pose_search_dist'] = context.param('max_robot_pose_search_dist',
                                                        size_x / 2.0)
        self.p = p
        self.base_desired_linear_vel = p['desired_linear_vel']
        if p['approach_velocity_scaling_dist'] > size_x / 2.0:
            self.log.warning('approach_velocity_scaling_dist is larger than forward costmap '
                             'extent, leading to permanent slowdown')
        if p['max_robot_pose_search_dist'] < 0.0:
            self.log.warning('Max robot search distance is negative, setting to max to search '
                             'every point on path for the closest value.')
            p['max_robot_pose_search_dist'] = math.inf
        if not p['use_fixed_curvature_lookahead'] and p['interpolate_curvature_after_goal']:
            self.log.warning('For interpolate_curvature_after_goal to be set to true, '
                             'use_fixed_curvature_lookahead should be true, it is currently set '
                             'to false. Disabling.')
            p['interpolate_curvature_after_goal'] = False
        if p['inflation_cost_scaling_factor'] <= 0.0:
            self.log.warning('The value inflation_cost_scaling_factor is incorrectly set, it '
                             'should be >0. Disabling cost regulated linear velocity scaling.')
            p['use_cost_regulated_linear_velocity_scaling'] = False
        self.control_duration = 1.0 / self.node.get_parameter('controller_frequency').value
        self.plan = np.zeros((0, 3))
        self.goal_dist_tol = 0.25
        self.reset()
        self._carrot_pub = self.node.create_lifecycle_publisher(
            PointStamped, 'lookahead_point', 1)
        self._rotating_pub = self.node.create_lifecycle_publisher(
            Bool, 'is_rotating_to_heading', 1)

    # --- lifecycle -----------------------------------------------------------------------
    def activate(self) -> None:
        self.log.info(f'Activating controller: {self.name} of type {TYPE}')

    def deactivate(self) -> None:
        self.log.info(f'Deactivating controller: {self.name} of type {TYPE}')

    def cleanup(self) -> None:
        self.log.info(f'Cleaning up controller: {self.name} of type {TYPE}')
        for pub in (self._carrot_pub, self._rotating_pub):
            self.node.destroy_lifecycle_publisher(pub)

    def reset(self) -> None:
        self.cancelling = self.finished_cancelling = self.reached_xy = False

    def cancel(self) -> bool:
        if not self.p['use_cancel_deceleration']:
            return True
        self.cancelling = True
        return self.finished_cancelling

    def set_plan(self, path: np.ndarray) -> None:
        self.reached_xy = False
        self.plan = np.asarray(path, dtype=np.float64).reshape(-1, 3)

    def set_speed_limit(self, speed_limit: float, percentage: bool) -> None:
        if speed_limit == 0.0:  # NO_SPEED_LIMIT
            self.p['desired_linear_vel'] = self.base_desired_linear_vel
        elif percentage:
            self.p['desired_linear_vel'] = self.base_desired_linear_vel * speed_limit / 100.0
        else:
            self.p['desired_linear_vel'] = speed_limit

    # --- the plan in the robot's frame ---------------------------------------------------
    def transform_global_plan(self, pose: Pose2D, plan_to_costmap: Pose2D) -> np.ndarray:
        """PathHandler::transformGlobalPlan: prune what is behind, keep what lies within the
        local costmap's extent, in the robot's frame."""
        if len(self.plan) == 0:
            raise InvalidPath('Received plan with zero length')
        if self.p['interpolate_curvature_after_goal'] and len(self.plan) == 1:
            raise InvalidPath('Received plan with length of one')
        robot = to_frame(plan_to_costmap, np.array([pose]))[0]
        upper = first_after_integrated_distance(self.plan, self.p['max_robot_pose_search_dist'])
        begin = closest_index(self.plan, robot[0], robot[1], max(upper, 1))
        if upper > 0 and len(self.plan) > 1 and begin == upper - 1:
            begin = max(upper - 2, 0)  # keep two points to interpolate the end direction
        costmap = self.costmap_ros.costmap
        extent = max(costmap.size_x, costmap.size_y) * costmap.resolution / 2.0
        far = np.hypot(self.plan[begin:, 0] - robot[0], self.plan[begin:, 1] - robot[1]) > extent
        end = begin + int(np.argmax(far)) if far.any() else len(self.plan)
        local = to_frame(pose, compose(plan_to_costmap, self.plan[begin:end]))
        self.plan = self.plan[begin:]
        if len(local) == 0:
            raise InvalidPath('Resulting plan has 0 poses in it.')
        return local

    # --- the command ---------------------------------------------------------------------
    def compute_velocity_commands(self, pose: Pose2D, speed: Pose2D, goal_checker: Any,
                                  plan_to_costmap: Pose2D) -> Pose2D:
        p = self.p
        if goal_checker is not None and hasattr(goal_checker, 'tolerances'):
            self.goal_dist_tol = goal_checker.tolerances()[0]
        plan = self.transform_global_plan(pose, plan_to_costmap)
        lookahead = reg.lookahead_distance(
            speed[0], p['lookahead_dist'], p['use_velocity_scaled_lookahead_dist'],
            p['lookahead_time'], p['min_lookahead_dist'], p['max_lookahead_dist'])
        curv_lookahead = p['curvature_lookahead_dist']
        if p['allow_reversing']:
            cusp = reg.find_velocity_sign_change(plan)
            lookahead, curv_lookahead = min(lookahead, cusp), min(curv_lookahead, cusp)
        carrot = reg.lookahead_point(lookahead, plan)
        self._publish_carrot(carrot, pose)
        curvature = reg.curvature(carrot[0], carrot[1])
        path_carrot = carrot
        if p['use_fixed_curvature_lookahead']:
            path_carrot = reg.lookahead_point(curv_lookahead, plan,
                                              p['interpolate_curvature_after_goal'])
            curvature = reg.curvature(path_carrot[0], path_carrot[1])
        sign = 1.0
        if p['allow_reversing']:
            sign = 1.0 if carrot[0] >= 0.0 else -1.0
        angle_to_path = math.atan2(path_carrot[1], path_carrot[0])
        if sign < 0.0:
            angle_to_path = (angle_to_path + 2 * math.pi) % (2 * math.pi) - math.pi
        rotating = True
        if self._should_rotate_to_goal_heading(carrot):
            linear, angular = 0.0, reg.rotate_to_heading(
                float(plan[-1, 2]), speed[2], p['rotate_to_heading_angular_vel'],
                p['max_angular_accel'], self.control_duration)
        elif p['use_rotate_to_heading'] and abs(angle_to_path) > p['rotate_to_heading_min_angle']:
            linear, angular = 0.0, reg.rotate_to_heading(
                angle_to_path, speed[2], p['rotate_to_heading_angular_vel'],
                p['max_angular_accel'], self.control_duration)
        else:
            rotating = False
            linear = self._constrained_speed(curvature, pose, plan, sign)
            if self.cancelling:
                linear = speed[0] - sign * self.control_duration * p['cancel_deceleration']
                if linear * sign <= 0.0:
                    linear, self.finished_cancelling = 0.0, True
            angular = linear * curvature
        if p['use_collision_detection'] and self._collision_imminent(
                pose, linear, angular, math.hypot(carrot[0], carrot[1])):
            raise NoValidControl('RegulatedPurePursuitController detected collision ahead!')
        self._rotating_pub.publish(Bool(data=rotating))
        return linear, 0.0, angular

    def _should_rotate_to_goal_heading(self, carrot: tuple[float, float, float]) -> bool:
        if not self.p['use_rotate_to_heading']:
            return False
        near = math.hypot(carrot[0], carrot[1]) < self.goal_dist_tol
        if self.p['stateful']:
            self.reached_xy = self.reached_xy or near
            return self.reached_xy
        return near

    def _constrained_speed(self, curvature: float, pose: Pose2D, plan: np.ndarray,
                           sign: float) -> float:
        """applyConstraints: the lower of the curvature and cost limits, not below the
        minimum speed, slowed on approach, within desired_linear_vel."""
        p = self.p
        desired = p['desired_linear_vel']
        curvature_vel = cost_vel = desired
        if p['use_regulated_linear_velocity_scaling']:
            curvature_vel = reg.curvature_constraint(desired, curvature,
                                                     p['regulated_linear_scaling_min_radius'])
        if p['use_cost_regulated_linear_velocity_scaling']:
            cost_vel = reg.cost_constraint(
                desired, self._cost_at(pose[0], pose[1]),
                self.costmap_ros.config.layered.inscribed_radius,
                p['inflation_cost_scaling_factor'], p['cost_scaling_dist'],
                p['cost_scaling_gain'])
        linear = max(min(cost_vel, curvature_vel), p['regulated_linear_scaling_min_speed'])
        linear = reg.approach_velocity_constraint(linear, plan, p['min_approach_linear_velocity'],
                                                  p['approach_velocity_scaling_dist'])
        return sign * min(max(abs(linear), 0.0), desired)

    # --- collisions ----------------------------------------------------------------------
    def _cost_at(self, x: float, y: float) -> float:
        """CollisionChecker::costAtPose."""
        with self.costmap_ros.lock:
            cell = self.costmap_ros.costmap.world_to_map(x, y)
            if cell is None:
                self.log.fatal('The dimensions of the costmap is too small to fully include '
                               "your robot's footprint, thusly the robot cannot proceed further")
                raise ControllerException(
                    'RegulatedPurePursuitController: Dimensions of the costmap are too small '
                    'to encapsulate the robot footprint at current speeds!')
            return float(self.costmap_ros.costmap.get_cost(*cell))

    def _footprint_cost(self, x: float, y: float, theta: float) -> float:
        """FootprintCollisionChecker::footprintCostAtPose: the highest cost on the outline of
        the footprint placed at the pose (LETHAL when part of it is off the map)."""
        costmap = self.costmap_ros.costmap
        outline = np.array(transform_footprint(x, y, theta,
                                               self.costmap_ros.config.layered.footprint))
        ends = np.roll(outline, -1, axis=0)
        steps = max(int(np.ceil(np.hypot(*(ends - outline).T).max() / costmap.resolution)), 1)
        t = np.linspace(0.0, 1.0, steps + 1)[None, :, None]
        points = (outline[:, None, :] * (1 - t) + ends[:, None, :] * t).reshape(-1, 2)
        mx, my, inside = costmap.world_to_map_array(points[:, 0], points[:, 1])
        if not inside.all():
            return float(LETHAL_OBSTACLE)
        return float(costmap.costmap[my, mx].max())

    def _in_collision(self, x: float, y: float, theta: float) -> bool:
        if self.costmap_ros.costmap.world_to_map(x, y) is None:
            self.log.warning(
                'The dimensions of the costmap is too small to successfully check for '
                'collisions as far ahead as requested. Proceed at your own risk, slow the '
                'robot, or increase your costmap size.', throttle_duration_sec=30.0)
            return False
        cost = self._footprint_cost(x, y, theta)
        if cost == NO_INFORMATION and self.costmap_ros.config.layered.track_unknown:
            return False
        return cost >= LETHAL_OBSTACLE

    def _collision_imminent(self, pose: Pose2D, linear: float, angular: float,
                            carrot_dist: float) -> bool:
        """CollisionChecker::isCollisionImminent: forward-simulate the command cell by cell
        up to the carrot or max_allowed_time_to_collision_up_to_carrot."""
        with self.costmap_ros.lock:
            if self._in_collision(*pose):
                return True
            resolution = self.costmap_ros.costmap.resolution
            if abs(linear) < 0.01 and abs(angular) > 0.01:
                radius = self.costmap_ros.config.layered.circumscribed_radius
                step = 2.0 * math.sin((resolution / 2) / radius) / abs(angular)
            elif abs(linear) > 1e-9:
                step = resolution / abs(linear)
            else:
                return False
            x, y, theta = pose
            i = 1
            while i * step < self.p['max_allowed_time_to_collision_up_to_carrot']:
                i += 1
                x += step * linear * math.cos(theta)
                y += step * linear * math.sin(theta)
                theta += step * angular
                if math.hypot(x - pose[0], y - pose[1]) > carrot_dist:
                    break
                if self._in_collision(x, y, theta):
                    return True
        return False

    def _publish_carrot(self, carrot: tuple[float, float, float], pose: Pose2D) -> None:
        msg = PointStamped()
        msg.header.frame_id = self.costmap_ros.config.settings['robot_base_frame']
        msg.header.stamp = self.node.get_clock().now().to_msg()
        msg.point.x, msg.point.y, msg.point.z = float(carrot[0]), float(carrot[1]), 0.01
        self._carrot_pub.publish(msg)
