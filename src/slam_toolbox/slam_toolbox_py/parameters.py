"""slam_toolbox's parameters: upstream's names and defaults (slam_toolbox_common.cpp,
slam_mapper.cpp, laser_utils.cpp, the Ceres solver plugin)."""

from __future__ import annotations

from dataclasses import fields

from rclpy.parameter import Parameter

from slam_toolbox_py.mapper import MapperParams

NODE = {
    'odom_frame': 'odom', 'map_frame': 'map', 'base_frame': 'base_footprint',
    'scan_topic': '/scan', 'map_name': '/map', 'mode': 'mapping',
    'use_map_saver': True, 'use_lifecycle_manager': False, 'debug_logging': False,
    'scan_queue_size': 1, 'throttle_scans': 1, 'position_covariance_scale': 1.0,
    'yaw_covariance_scale': 1.0, 'enable_interactive_mode': False,
    'transform_timeout': 0.5, 'minimum_time_interval': 0.5, 'tf_buffer_duration': 30.0,
    'transform_publish_period': 0.05, 'map_update_interval': 10.0, 'resolution': 0.05,
    'max_laser_range': 25.0, 'stack_size_to_use': 40_000_000,
    'map_file_name': '', 'map_start_pose': Parameter.Type.DOUBLE_ARRAY,
    'map_start_at_dock': Parameter.Type.BOOL, 'localization_on_configure': True,
    # the solver plugin's: accepted, the optimiser is scipy's (docs/slam.md)
    'solver_plugin': 'solver_plugins::CeresSolver',
    'ceres_linear_solver': 'SPARSE_NORMAL_CHOLESKY', 'ceres_preconditioner': 'SCHUR_JACOBI',
    'ceres_trust_strategy': 'LEVENBERG_MARQUARDT', 'ceres_dogleg_type': 'TRADITIONAL_DOGLEG',
    'ceres_loss_function': 'None',
    # Karto's, accepted without effect here (docs/slam.md: how we differ)
    'use_scan_barycenter': True, 'use_response_expansion': True,
    # the occupancy grid's (Karto's OccupancyGrid)
    'min_pass_through': 2, 'occupancy_threshold': 0.1,
}
# the lifelong node's, read by none of ours but accepted in a shared params file
ACCEPTED = {
    'lifelong_search_use_tree': False, 'lifelong_minimum_score': 0.1,
    'lifelong_iou_match': 0.85, 'lifelong_node_removal_score': 0.04,
    'lifelong_overlap_score_scale': 0.06, 'lifelong_constraint_multiplier': 0.08,
    'lifelong_nearby_penalty': 0.001, 'lifelong_candidates_scale': 0.03,
}
# set by the node itself, as upstream's
STATE = {'paused_new_measurements': False, 'paused_processing': False,
         'interactive_mode': False}


def mapper_defaults() -> dict:
    defaults = MapperParams()
    return {f.name: getattr(defaults, f.name) for f in fields(MapperParams)}


def all_defaults() -> dict:
    return {**NODE, **mapper_defaults(), **ACCEPTED}


def mapper_params(values: dict) -> MapperParams:
    return MapperParams(**{f.name: values[f.name] for f in fields(MapperParams)})
