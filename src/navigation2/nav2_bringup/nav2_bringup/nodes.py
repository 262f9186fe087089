"""What nav2_bringup's launch files start, and how: the nodes as separate processes
(use_composition:=False) or as components of one `nav2_container` process.

A node whose package or executable this workspace does not build (route_server,
docking_server, and any server not written yet) is left out with one warning line, and left
out of its lifecycle manager's node_names too, so the manager never waits for it.
"""

from __future__ import annotations

import json
import os
from dataclasses import dataclass, field
from importlib import metadata

from ament_index_python.packages import PackageNotFoundError, get_package_prefix
from launch.launch_context import LaunchContext
from launch_ros.actions import Node

import launch


@dataclass(frozen=True)
class Server:
    name: str
    package: str
    executable: str
    plugin: str  # upstream's component name
    remappings: tuple[tuple[str, str], ...] = ()
    # processes that set the node name themselves: no `__node` remap, which would also
    # rename the costmap node the server creates in its process
    own_name: bool = True


# Upstream remaps /tf to tf for namespaced robots. Without a namespace the rule would only
# harm: a node in a namespace of its own (a server's global_costmap) would then listen on
# /global_costmap/tf. So it is given with use_namespace:=True only.
TF = (('/tf', 'tf'), ('/tf_static', 'tf_static'))
NAV = (('cmd_vel', 'cmd_vel_nav'),)

NAVIGATION = (
    Server('controller_server', 'nav2_controller', 'controller_server',
           'nav2_controller::ControllerServer', NAV),
    Server('smoother_server', 'nav2_smoother', 'smoother_server',
           'nav2_smoother::SmootherServer'),
    Server('planner_server', 'nav2_planner', 'planner_server', 'nav2_planner::PlannerServer'),
    Server('route_server', 'nav2_route', 'route_server', 'nav2_route::RouteServer'),
    Server('behavior_server', 'nav2_behaviors', 'behavior_server',
           'behavior_server::BehaviorServer', NAV),
    Server('velocity_smoother', 'nav2_velocity_smoother', 'velocity_smoother',
           'nav2_velocity_smoother::VelocitySmoother', NAV),
    Server('collision_monitor', 'nav2_collision_monitor', 'collision_monitor',
           'nav2_collision_monitor::CollisionMonitor'),
    Server('bt_navigator', 'nav2_bt_navigator', 'bt_navigator',
           'nav2_bt_navigator::BtNavigator'),
    Server('waypoint_follower', 'nav2_waypoint_follower', 'waypoint_follower',
           'nav2_waypoint_follower::WaypointFollower'),
    Server('docking_server', 'opennav_docking', 'opennav_docking',
           'opennav_docking::DockingServer'),
)
LOCALIZATION = (
    Server('map_server', 'nav2_map_server', 'map_server', 'nav2_map_server::MapServer'),
    Server('amcl', 'nav2_amcl', 'amcl', 'nav2_amcl::AmclNode'),
)
MANAGER = Server('lifecycle_manager', 'nav2_lifecycle_manager', 'lifecycle_manager',
                 'nav2_lifecycle_manager::LifecycleManager', own_name=False)


def is_built(server: Server) -> bool:
    try:
        prefix = get_package_prefix(server.package)
    except (PackageNotFoundError, ValueError):
        return False
    return os.access(os.path.join(prefix, 'lib', server.package, server.executable), os.X_OK)


def entry_point(server: Server) -> str:
    """'module:function' of the executable (the container imports the module's node class)."""
    for ep in metadata.distribution(server.package).entry_points:
        if ep.group == 'console_scripts' and ep.name == server.executable:
            return ep.value
    raise LookupError(f'{server.package} has no executable {server.executable}')


def built_servers(servers: tuple[Server, ...]) -> list[Server]:
    """The servers that exist here; one warning line for each that does not."""
    logger = launch.logging.get_logger('launch')
    kept = []
    for server in servers:
        if is_built(server):
            kept.append(server)
        else:
            logger.warning(f'{server.name} is not built here; left out')
    return kept


@dataclass
class Bringup:
    """The resolved launch arguments a group of nodes is started with."""

    params_file: str
    use_sim_time: bool
    autostart: bool
    use_respawn: bool
    log_level: str
    tf_remaps: tuple[tuple[str, str], ...] = ()
    extra: dict[str, dict] = field(default_factory=dict)  # per node: parameter overrides

    @classmethod
    def from_context(cls, context: LaunchContext) -> Bringup:
        conf = context.launch_configurations

        def flag(name: str, default: str) -> bool:
            return conf.get(name, default).strip().lower() in ('true', '1', 'yes')

        return cls(params_file=conf['params_file'],
                   use_sim_time=flag('use_sim_time', 'false'),
                   autostart=flag('autostart', 'true'),
                   use_respawn=flag('use_respawn', 'false'),
                   log_level=conf.get('log_level', 'info'),
                   tf_remaps=TF if flag('use_namespace', 'false') else ())


def node_actions(servers: list[Server], manager: str, setup: Bringup) -> list[Node]:
    """One process per server and the lifecycle manager named `manager`."""
    actions = []
    for server in servers:
        actions.append(Node(
            package=server.package, executable=server.executable,
            name=None if server.own_name else server.name, output='screen',
            respawn=setup.use_respawn, respawn_delay=2.0,
            parameters=[setup.params_file, {'use_sim_time': setup.use_sim_time},
                        setup.extra.get(server.name, {})],
            arguments=['--ros-args', '--log-level', setup.log_level],
            remappings=list(setup.tf_remaps + server.remappings)))
    actions.append(Node(
        package=MANAGER.package, executable=MANAGER.executable, name=manager, output='screen',
        arguments=['--ros-args', '--log-level', setup.log_level],
        parameters=[{'use_sim_time': setup.use_sim_time, 'autostart': setup.autostart,
                     'node_names': [server.name for server in servers]}]))
    return actions


def components(servers: list[Server], manager: str, setup: Bringup) -> list[dict]:
    """The container's description of each component: its class and its own arguments."""
    described = []
    for server in servers:
        args = []
        for src, dst in server.remappings:
            args += ['-r', f'{src}:={dst}']
        for key, value in setup.extra.get(server.name, {}).items():
            args += ['-p', f'{key}:={json.dumps(value)}']
        described.append({'name': server.name, 'entry_point': entry_point(server),
                          'arguments': args})
    names = json.dumps([server.name for server in servers])
    described.append({
        'name': manager, 'entry_point': entry_point(MANAGER),
        'arguments': ['-r', f'__node:={manager}', '-p', f'node_names:={names}',
                      '-p', f'autostart:={str(setup.autostart).lower()}']})
    return described


def container_action(described: list[dict], name: str, setup: Bringup) -> Node:
    # The container names its own node: a `__node` remap on its command line would rename
    # every node in the process (the servers' costmaps get the global arguments too).
    return Node(
        package='nav2_bringup', executable='nav2_container', output='screen',
        parameters=[setup.params_file, {'use_sim_time': setup.use_sim_time}],
        arguments=[json.dumps(described), name, '--ros-args', '--log-level', setup.log_level],
        remappings=list(setup.tf_remaps))


# bringup_launch.py gathers the components of its included launch files into one container
_GATHERING: dict[int, list[dict]] = {}


def start_gathering(context: LaunchContext) -> None:
    _GATHERING[id(context)] = []


def gather(context: LaunchContext, described: list[dict]) -> bool:
    """Add components to the container bringup_launch.py starts; False if none is gathering."""
    gathered = _GATHERING.get(id(context))
    if gathered is None:
        return False
    gathered.extend(described)
    return True


def stop_gathering(context: LaunchContext) -> list[dict]:
    return _GATHERING.pop(id(context), [])
