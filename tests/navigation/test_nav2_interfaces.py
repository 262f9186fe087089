"""nav2_msgs (Nav2 Jazzy 1.3.x) and geographic_msgs (1.0.x) equal upstream's, field for field.

Upstream's definitions are written down below without their comments ('|' between lines,
'---' between parts). Each is compared with what rosidl generated: the fields in order with
their types (the order and types are the wire format), the constants and the defaults.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from ament_index_python.packages import get_package_share_directory

from support import interface_type

NAV2_MSGS = {
    'msg/BehaviorTreeLog': 'builtin_interfaces/Time timestamp|BehaviorTreeStatusChange[] event_log',
    'msg/BehaviorTreeStatusChange': 'builtin_interfaces/Time timestamp|string node_name|'
    'uint16 uid|string previous_status|string current_status',
    'msg/CollisionDetectorState': 'string[] polygons|bool[] detections',
    'msg/CollisionMonitorState': 'uint8 DO_NOTHING=0|uint8 STOP=1|uint8 SLOWDOWN=2|'
    'uint8 APPROACH=3|uint8 LIMIT=4|uint8 action_type|string polygon_name',
    'msg/Costmap': 'std_msgs/Header header|CostmapMetaData metadata|uint8[] data',
    'msg/CostmapFilterInfo': 'std_msgs/Header header|uint8 type|string filter_mask_topic|'
    'float32 base|float32 multiplier',
    'msg/CostmapMetaData': 'builtin_interfaces/Time map_load_time|'
    'builtin_interfaces/Time update_time|string layer|float32 resolution|uint32 size_x|'
    'uint32 size_y|geometry_msgs/Pose origin',
    'msg/CostmapUpdate': 'std_msgs/Header header|uint32 x|uint32 y|uint32 size_x|'
    'uint32 size_y|uint8[] data',
    'msg/EdgeCost': 'uint16 edgeid|float32 cost',
    'msg/MissedWaypoint': 'uint32 index|geometry_msgs/PoseStamped goal|uint16 error_code',
    'msg/Particle': 'geometry_msgs/Pose pose|float64 weight',
    'msg/ParticleCloud': 'std_msgs/Header header|Particle[] particles',
    'msg/Route': 'std_msgs/Header header|float32 route_cost|RouteNode[] nodes|'
    'RouteEdge[] edges',
    'msg/RouteEdge': 'uint16 edgeid|geometry_msgs/Point start|geometry_msgs/Point end',
    'msg/RouteNode': 'uint16 nodeid|geometry_msgs/Point position',
    'msg/SpeedLimit': 'std_msgs/Header header|bool percentage|float64 speed_limit',
    'msg/VoxelGrid': 'std_msgs/Header header|uint32[] data|geometry_msgs/Point32 origin|'
    'geometry_msgs/Vector3 resolutions|uint32 size_x|uint32 size_y|uint32 size_z',
    'srv/ClearCostmapAroundPose': 'geometry_msgs/PoseStamped pose|float64 reset_distance'
    '---std_msgs/Empty response',
    'srv/ClearCostmapAroundRobot': 'float32 reset_distance---std_msgs/Empty response',
    'srv/ClearCostmapExceptRegion': 'float32 reset_distance---std_msgs/Empty response',
    'srv/ClearEntireCostmap': 'std_msgs/Empty request---std_msgs/Empty response',
    'srv/DynamicEdges': 'uint16[] closed_edges|uint16[] opened_edges|EdgeCost[] adjust_edges'
    '---bool success',
    'srv/GetCost': 'bool use_footprint|float32 x|float32 y|float32 theta---float32 cost',
    'srv/GetCostmap': 'nav2_msgs/CostmapMetaData specs---nav2_msgs/Costmap map',
    'srv/IsPathValid': 'nav_msgs/Path path---bool is_valid|int32[] invalid_pose_indices',
    'srv/LoadMap': 'string map_url---uint8 RESULT_SUCCESS=0|uint8 RESULT_MAP_DOES_NOT_EXIST=1|'
    'uint8 RESULT_INVALID_MAP_DATA=2|uint8 RESULT_INVALID_MAP_METADATA=3|'
    'uint8 RESULT_UNDEFINED_FAILURE=255|nav_msgs/OccupancyGrid map|uint8 result',
    'srv/ManageLifecycleNodes': 'uint8 STARTUP=0|uint8 PAUSE=1|uint8 RESUME=2|uint8 RESET=3|'
    'uint8 SHUTDOWN=4|uint8 CONFIGURE=5|uint8 CLEANUP=6|uint8 command---bool success',
    'srv/ReloadDockDatabase': 'string filepath---bool success',
    'srv/SaveMap': 'string map_topic|string map_url|string image_format|string map_mode|'
    'float32 free_thresh|float32 occupied_thresh---bool result',
    'srv/SetInitialPose': 'geometry_msgs/PoseWithCovarianceStamped pose---',
    'srv/SetRouteGraph': 'string graph_filepath---bool success',
    'srv/Toggle': 'bool enable---bool success|string message',
}
_BEHAVIOR_RESULT = ('builtin_interfaces/Duration total_elapsed_time|uint16 error_code|'
                    'string error_msg')
_ROUTE_GOAL = ('uint16 start_id|geometry_msgs/PoseStamped start|uint16 goal_id|'
               'geometry_msgs/PoseStamped goal|bool use_start|bool use_poses')
_ROUTE_CODES = ('uint16 NONE=0|uint16 UNKNOWN=400|uint16 TF_ERROR=401|uint16 NO_VALID_GRAPH=402|'
                'uint16 INDETERMINANT_NODES_ON_GRAPH=403|uint16 TIMEOUT=404|'
                'uint16 NO_VALID_ROUTE=405|')
_PLANNER_CODES = ('uint16 INVALID_PLANNER={0}1|uint16 TF_ERROR={0}2|'
                  'uint16 START_OUTSIDE_MAP={0}3|uint16 GOAL_OUTSIDE_MAP={0}4|'
                  'uint16 START_OCCUPIED={0}5|uint16 GOAL_OCCUPIED={0}6|uint16 TIMEOUT={0}7|'
                  'uint16 NO_VALID_PATH={0}8|')
_PLANNER_RESULT = ('nav_msgs/Path path|builtin_interfaces/Duration planning_time|'
                   'uint16 error_code|string error_msg---')
NAV2_ACTIONS = {
    'action/AssistedTeleop': 'builtin_interfaces/Duration time_allowance---uint16 NONE=0|'
    'uint16 UNKNOWN=730|uint16 TIMEOUT=731|uint16 TF_ERROR=732|' + _BEHAVIOR_RESULT +
    '---builtin_interfaces/Duration current_teleop_duration',
    'action/BackUp': 'geometry_msgs/Point target|float32 speed|'
    'builtin_interfaces/Duration time_allowance---uint16 NONE=0|uint16 UNKNOWN=710|'
    'uint16 TIMEOUT=711|uint16 TF_ERROR=712|uint16 INVALID_INPUT=713|'
    'uint16 COLLISION_AHEAD=714|' + _BEHAVIOR_RESULT + '---float32 distance_traveled',
    'action/ComputeAndTrackRoute': _ROUTE_GOAL + '---' + _ROUTE_CODES +
    'uint16 OPERATION_FAILED=406|uint16 INVALID_EDGE_SCORER_USE=407|'
    'builtin_interfaces/Duration execution_duration|uint16 error_code 0---'
    'uint16 last_node_id|uint16 next_node_id|uint16 current_edge_id|Route route|'
    'nav_msgs/Path path|string[] operations_triggered|bool rerouted',
    'action/ComputePathThroughPoses': 'geometry_msgs/PoseStamped[] goals|'
    'geometry_msgs/PoseStamped start|string planner_id|bool use_start---uint16 NONE=0|'
    'uint16 UNKNOWN=300|' + _PLANNER_CODES.format(30) + 'uint16 NO_VIAPOINTS_GIVEN=309|' +
    _PLANNER_RESULT,
    'action/ComputePathToPose': 'geometry_msgs/PoseStamped goal|'
    'geometry_msgs/PoseStamped start|string planner_id|bool use_start---uint16 NONE=0|'
    'uint16 UNKNOWN=200|' + _PLANNER_CODES.format(20) + _PLANNER_RESULT,
    'action/ComputeRoute': _ROUTE_GOAL + '---' + _ROUTE_CODES +
    'uint16 INVALID_EDGE_SCORER_USE=407|builtin_interfaces/Duration planning_time|'
    'nav_msgs/Path path|Route route|uint16 error_code 0---',
    'action/DockRobot': 'bool use_dock_id True|string dock_id|'
    'geometry_msgs/PoseStamped dock_pose|string dock_type|float32 max_staging_time 1000.0|'
    'bool navigate_to_staging_pose True---uint16 NONE=0|uint16 DOCK_NOT_IN_DB=901|'
    'uint16 DOCK_NOT_VALID=902|uint16 FAILED_TO_STAGE=903|uint16 FAILED_TO_DETECT_DOCK=904|'
    'uint16 FAILED_TO_CONTROL=905|uint16 FAILED_TO_CHARGE=906|uint16 UNKNOWN=999|'
    'bool success True|uint16 error_code 0|uint16 num_retries 0|string error_msg---'
    'uint16 NONE=0|uint16 NAV_TO_STAGING_POSE=1|uint16 INITIAL_PERCEPTION=2|'
    'uint16 CONTROLLING=3|uint16 WAIT_FOR_CHARGE=4|uint16 RETRY=5|uint16 state|'
    'builtin_interfaces/Duration docking_time|uint16 num_retries 0',
    'action/DriveOnHeading': 'geometry_msgs/Point target|float32 speed|'
    'builtin_interfaces/Duration time_allowance---uint16 NONE=0|uint16 UNKNOWN=720|'
    'uint16 TIMEOUT=721|uint16 TF_ERROR=722|uint16 COLLISION_AHEAD=723|'
    'uint16 INVALID_INPUT=724|' + _BEHAVIOR_RESULT + '---float32 distance_traveled',
    'action/DummyBehavior': 'std_msgs/String command---' + _BEHAVIOR_RESULT + '---',
    'action/FollowGPSWaypoints': 'uint32 number_of_loops|uint32 goal_index 0|'
    'geographic_msgs/GeoPose[] gps_poses---uint16 NONE=0|uint16 UNKNOWN=600|'
    'uint16 TASK_EXECUTOR_FAILED=601|MissedWaypoint[] missed_waypoints|int16 error_code|'
    'string error_msg---uint32 current_waypoint',
    'action/FollowObject': 'string pose_topic|string tracked_frame|'
    'builtin_interfaces/Duration max_duration---uint16 NONE=0|uint16 TF_ERROR=901|'
    'uint16 FAILED_TO_DETECT_OBJECT=902|uint16 FAILED_TO_CONTROL=903|uint16 TIMEOUT=904|'
    'uint16 UNKNOWN=999|builtin_interfaces/Duration total_elapsed_time|uint16 error_code 0|'
    'uint16 num_retries 0|string error_msg---uint16 NONE=0|uint16 INITIAL_PERCEPTION=1|'
    'uint16 CONTROLLING=2|uint16 STOPPING=3|uint16 RETRY=4|uint16 state|'
    'builtin_interfaces/Duration following_time|uint16 num_retries 0',
    'action/FollowPath': 'nav_msgs/Path path|string controller_id|string goal_checker_id|'
    'string progress_checker_id---uint16 NONE=0|uint16 UNKNOWN=100|'
    'uint16 INVALID_CONTROLLER=101|uint16 TF_ERROR=102|uint16 INVALID_PATH=103|'
    'uint16 PATIENCE_EXCEEDED=104|uint16 FAILED_TO_MAKE_PROGRESS=105|'
    'uint16 NO_VALID_CONTROL=106|uint16 CONTROLLER_TIMED_OUT=107|std_msgs/Empty result|'
    'uint16 error_code|string error_msg---float32 distance_to_goal|float32 speed',
    'action/FollowWaypoints': 'uint32 number_of_loops|uint32 goal_index 0|'
    'geometry_msgs/PoseStamped[] poses---uint16 NONE=0|uint16 UNKNOWN=600|'
    'uint16 TASK_EXECUTOR_FAILED=601|MissedWaypoint[] missed_waypoints|uint16 error_code|'
    'string error_msg---uint32 current_waypoint',
    'action/NavigateThroughPoses': 'geometry_msgs/PoseStamped[] poses|string behavior_tree---'
    'uint16 NONE=0|uint16 error_code|string error_msg---'
    'geometry_msgs/PoseStamped current_pose|builtin_interfaces/Duration navigation_time|'
    'builtin_interfaces/Duration estimated_time_remaining|int16 number_of_recoveries|'
    'float32 distance_remaining|int16 number_of_poses_remaining',
    'action/NavigateToPose': 'geometry_msgs/PoseStamped pose|string behavior_tree---'
    'uint16 NONE=0|uint16 error_code|string error_msg---'
    'geometry_msgs/PoseStamped current_pose|builtin_interfaces/Duration navigation_time|'
    'builtin_interfaces/Duration estimated_time_remaining|int16 number_of_recoveries|'
    'float32 distance_remaining',
    'action/SmoothPath': 'nav_msgs/Path path|string smoother_id|'
    'builtin_interfaces/Duration max_smoothing_duration|bool check_for_collisions---'
    'uint16 NONE=0|uint16 UNKNOWN=500|uint16 INVALID_SMOOTHER=501|uint16 TIMEOUT=502|'
    'uint16 SMOOTHED_PATH_IN_COLLISION=503|uint16 FAILED_TO_SMOOTH_PATH=504|'
    'uint16 INVALID_PATH=505|nav_msgs/Path path|builtin_interfaces/Duration smoothing_duration|'
    'bool was_completed|uint16 error_code|string error_msg---',
    'action/Spin': 'float32 target_yaw|builtin_interfaces/Duration time_allowance---'
    'uint16 NONE=0|uint16 UNKNOWN=700|uint16 TIMEOUT=701|uint16 TF_ERROR=702|'
    'uint16 COLLISION_AHEAD=703|' + _BEHAVIOR_RESULT + '---float32 angular_distance_traveled',
    'action/UndockRobot': 'string dock_type|float32 max_undocking_time 30.0---uint16 NONE=0|'
    'uint16 DOCK_NOT_VALID=902|uint16 FAILED_TO_CONTROL=905|uint16 UNKNOWN=999|'
    'bool success True|uint16 error_code 0|string error_msg---',
    'action/Wait': 'builtin_interfaces/Duration time---' + _BEHAVIOR_RESULT +
    '---builtin_interfaces/Duration time_left',
}
_UUID = 'unique_identifier_msgs/UUID'
GEOGRAPHIC_MSGS = {
    'msg/BoundingBox': 'GeoPoint min_pt|GeoPoint max_pt',
    'msg/GeoPath': 'std_msgs/Header header|geographic_msgs/GeoPoseStamped[] poses',
    'msg/GeoPoint': 'float64 latitude|float64 longitude|float64 altitude',
    'msg/GeoPointStamped': 'std_msgs/Header header|geographic_msgs/GeoPoint position',
    'msg/GeoPose': 'GeoPoint position|geometry_msgs/Quaternion orientation',
    'msg/GeoPoseStamped': 'std_msgs/Header header|geographic_msgs/GeoPose pose',
    'msg/GeoPoseWithCovariance': 'GeoPose pose|float64[36] covariance',
    'msg/GeoPoseWithCovarianceStamped': 'std_msgs/Header header|'
    'geographic_msgs/GeoPoseWithCovariance pose',
    'msg/GeographicMap': f'std_msgs/Header header|{_UUID} id|BoundingBox bounds|'
    'WayPoint[] points|MapFeature[] features|KeyValue[] props',
    'msg/GeographicMapChanges': f'std_msgs/Header header|GeographicMap diffs|{_UUID}[] deletes',
    'msg/KeyValue': 'string key|string value',
    'msg/MapFeature': f'{_UUID} id|{_UUID}[] components|KeyValue[] props',
    'msg/RouteNetwork': f'std_msgs/Header header|{_UUID} id|BoundingBox bounds|'
    'WayPoint[] points|RouteSegment[] segments|KeyValue[] props',
    'msg/RoutePath': f'std_msgs/Header header|{_UUID} network|{_UUID}[] segments|'
    'KeyValue[] props',
    'msg/RouteSegment': f'{_UUID} id|{_UUID} start|{_UUID} end|KeyValue[] props',
    'msg/WayPoint': f'{_UUID} id|GeoPoint position|KeyValue[] props',
    'srv/GetGeoPath': 'geographic_msgs/GeoPoint start|geographic_msgs/GeoPoint goal---'
    f'bool success|string status|geographic_msgs/GeoPath plan|{_UUID} network|'
    f'{_UUID} start_seg|{_UUID} goal_seg|float64 distance',
    'srv/GetGeographicMap': 'string url|BoundingBox bounds---bool success|string status|'
    'GeographicMap map',
    'srv/GetRoutePlan': f'{_UUID} network|{_UUID} start|{_UUID} goal---bool success|'
    'string status|RoutePath plan',
    'srv/UpdateGeographicMap': 'GeographicMapChanges updates---bool success|string status',
}
DEFINITIONS = {**{f'nav2_msgs/{k}': v for k, v in {**NAV2_MSGS, **NAV2_ACTIONS}.items()},
               **{f'geographic_msgs/{k}': v for k, v in GEOGRAPHIC_MSGS.items()}}
PARTS = {'msg': (None,), 'srv': ('Request', 'Response'), 'action': ('Goal', 'Result', 'Feedback')}
# .msg primitive -> the name rosidl's Python classes give it
PRIMITIVES = {'bool': 'boolean', 'byte': 'octet', 'char': 'uint8', 'float32': 'float',
              'float64': 'double', 'string': 'string', **{
                  f'{s}int{n}': f'{s}int{n}' for s in ('', 'u') for n in (8, 16, 32, 64)}}
DEFAULT_WORDS = {'True': True, 'False': False}


def rosidl_type(package: str, text: str) -> str:
    base, _, array = text.partition('[')
    if base in PRIMITIVES:
        name = PRIMITIVES[base]
    else:
        name = base if '/' in base else f'{package}/{base}'
    if not array:
        return name
    size = array.rstrip(']')
    return f'{name}[{size}]' if size else f'sequence<{name}>'


def expected_parts(name: str) -> list[tuple[str | None, dict, dict, dict]]:
    """(part, fields, constants, defaults) of each part of an interface."""
    package, kind, _ = name.split('/')
    parts = []
    for part, text in zip(PARTS[kind], DEFINITIONS[name].split('---'), strict=True):
        fields, constants, defaults = {}, {}, {}
        for line in filter(None, text.split('|')):
            words = line.split()
            if '=' in line:
                constant, value = words[1].split('=')
                constants[constant] = int(value)
                continue
            fields[words[1]] = rosidl_type(package, words[0])
            if len(words) == 3:
                defaults[words[1]] = DEFAULT_WORDS.get(words[2]) if words[2] in DEFAULT_WORDS \
                    else float(words[2])
        parts.append((part, fields, constants, defaults))
    return parts


@pytest.mark.parametrize('name', sorted(DEFINITIONS))
def test_generated_interface_equals_upstream(name):
    interface = interface_type(name)
    for part, fields, constants, defaults in expected_parts(name):
        cls = getattr(interface, part) if part else interface
        # get_fields_and_field_types() keeps the definition's order: the wire order
        assert list(cls.get_fields_and_field_types().items()) == list(fields.items()), part
        generated_constants = {key: value for key, value in
                               type(cls).__dict__.get('_' + type(cls).__name__ + '__constants',
                                                      {}).items()}
        assert generated_constants == constants, part
        instance = cls()
        assert {key: getattr(instance, key) for key in defaults} == defaults, part


@pytest.mark.parametrize('package, count', [('nav2_msgs', 17 + 15 + 19),
                                            ('geographic_msgs', 16 + 4)])
def test_interface_set_is_complete(package, count):
    share = Path(get_package_share_directory(package))
    installed = {f'{package}/{p.parent.name}/{p.stem}'
                 for kind in PARTS for p in (share / kind).glob(f'*.{kind}')}
    expected = {name for name in DEFINITIONS if name.startswith(package + '/')}
    assert installed == expected
    assert len(installed) == count
