"""The RViz page's Nav2 parts, as nav2_rviz_plugins gives rviz2: the ParticleCloud display,
the "Nav2 Goal" tool and the "Navigation 2" panel.

- GET /api/rviz/particles?topic=/particle_cloud: the latest nav2_msgs/ParticleCloud (best
  effort, as amcl publishes it) as {frame, seq, particles: [[x, y, qz, qw, weight], ...]}.
- POST /api/rviz/nav2/goal {frame, x, y, yaw}: a navigate_to_pose goal
  (nav2_msgs/action/NavigateToPose), replacing the page's previous one.
- POST /api/rviz/nav2/cancel: cancels it.
- POST /api/rviz/nav2/manage {command: startup|pause|resume|reset}: the command to
  lifecycle_manager_navigation and lifecycle_manager_localization (ManageLifecycleNodes),
  localization first on startup/resume, navigation first on pause/reset (as the panel does).
- GET /api/rviz/nav2/state: navigation and localization state (each manager's is_active),
  the goal's status, its latest feedback and its result.
"""

from __future__ import annotations

import asyncio
import math
from typing import Any

from aiohttp import web

from rqt_web.forms import MAX_TOPIC, absolute_topic

NAVIGATE = ('navigate_to_pose', 'nav2_msgs/action/NavigateToPose')
MANAGERS = ('lifecycle_manager_localization', 'lifecycle_manager_navigation')
COMMANDS = {'startup': 0, 'pause': 1, 'resume': 2, 'reset': 3}
SERVICE_WAIT = 5.0  # s a manage_nodes or is_active call may take before it counts as absent
ACTION_WAIT = 5.0  # s for navigate_to_pose to be discovered


def _nav2(app: web.Application) -> dict:
    return app.setdefault('rviz_nav2', {
        'goal': None, 'handle': None, 'status': 'none', 'feedback': None, 'result': None,
        'goals': 0, 'states': {m: 'unknown' for m in MANAGERS}, 'polling': False,
        'particles': {}})


# ------------------------------------------------------------------ ParticleCloud

async def particles_route(request: web.Request) -> web.Response:
    topic = request.query.get('topic', '/particle_cloud')
    if not absolute_topic(topic):
        raise web.HTTPBadRequest(text=f'topic must be an absolute topic name, got {topic!r}\n')
    app = request.app
    clouds = _nav2(app)['particles']
    if topic not in clouds:
        from rclpy.qos import qos_profile_sensor_data
        clouds[topic] = {'seq': 0, 'msg': None}

        def received(msg: Any) -> None:
            clouds[topic] = {'seq': clouds[topic]['seq'] + 1, 'msg': msg}
        # amcl publishes with the sensor data profile (best effort): a reliable
        # subscription would never match it.
        await app['bridge'].subscribe(topic, 'nav2_msgs/msg/ParticleCloud', received,
                                      qos=qos_profile_sensor_data)
    seq, msg = clouds[topic]['seq'], clouds[topic]['msg']
    if msg is None:
        return web.json_response({'topic': topic, 'seq': 0, 'frame': None, 'particles': []})
    particles = [[p.pose.position.x, p.pose.position.y, p.pose.orientation.z,
                  p.pose.orientation.w, p.weight] for p in msg.particles]
    return web.json_response({'topic': topic, 'seq': seq, 'frame': msg.header.frame_id,
                              'particles': particles})


# ------------------------------------------------------------------ Nav2 Goal

def _goal_pose(body: Any) -> tuple[str, float, float, float]:
    """frame, x, y, yaw of a Nav2 Goal request; ValueError naming the field otherwise."""
    if not isinstance(body, dict):
        raise ValueError('the body must be a JSON object {frame, x, y, yaw}')
    frame = body.get('frame', 'map')
    if not isinstance(frame, str) or not frame or len(frame) > MAX_TOPIC:
        raise ValueError(f'frame must be a frame id, got {frame!r}')
    values = []
    for key in ('x', 'y', 'yaw'):
        value = body.get(key, 0.0)
        if isinstance(value, bool) or not isinstance(value, (int, float)) \
                or not math.isfinite(value):
            raise ValueError(f'{key} must be a finite number, got {value!r}')
        values.append(float(value))
    return frame, values[0], values[1], values[2]


async def goal_route(request: web.Request) -> web.Response:
    try:
        frame, x, y, yaw = _goal_pose(await request.json())
    except ValueError as error:  # json's JSONDecodeError is a ValueError too
        raise web.HTTPBadRequest(text=f'Nav2 Goal: {error}\n') from None
    app = request.app
    bridge, nav2 = app['bridge'], _nav2(app)
    from nav2_msgs.action import NavigateToPose
    goal = NavigateToPose.Goal()
    goal.pose.header.frame_id = frame
    goal.pose.header.stamp = await bridge.run(lambda: bridge.node.get_clock().now().to_msg())
    goal.pose.pose.position.x, goal.pose.pose.position.y = x, y
    goal.pose.pose.orientation.z, goal.pose.pose.orientation.w = math.sin(yaw / 2), \
        math.cos(yaw / 2)
    client = await bridge.action_client(*NAVIGATE)
    deadline = asyncio.get_running_loop().time() + ACTION_WAIT
    while not client.server_is_ready():
        if asyncio.get_running_loop().time() > deadline:
            raise web.HTTPServiceUnavailable(text='navigate_to_pose action server is not '
                                             'available: is Nav2 running?\n')
        await asyncio.sleep(0.05)
    nav2['goals'] += 1
    number = nav2['goals']

    def feedback(msg: Any) -> None:  # on the ROS thread
        f = msg.feedback
        values = {'distance_remaining': f.distance_remaining,
                  'navigation_time': f.navigation_time.sec + f.navigation_time.nanosec * 1e-9,
                  'estimated_time_remaining': f.estimated_time_remaining.sec
                  + f.estimated_time_remaining.nanosec * 1e-9,
                  'number_of_recoveries': f.number_of_recoveries,
                  'current_pose': [f.current_pose.pose.position.x,
                                   f.current_pose.pose.position.y]}

        def store() -> None:
            if nav2['goals'] == number:
                nav2['feedback'] = values
        bridge.loop.call_soon_threadsafe(store)
    sent = await bridge.run(lambda: client.send_goal_async(goal, feedback))
    handle = await bridge.to_asyncio(sent)
    if nav2['goals'] != number:  # a newer goal was sent meanwhile
        return web.json_response({'accepted': handle.accepted, 'replaced': True})
    nav2.update(goal={'frame': frame, 'x': x, 'y': y, 'yaw': yaw}, feedback=None,
                result=None, handle=handle if handle.accepted else None,
                status='active' if handle.accepted else 'rejected')
    if handle.accepted:
        nav2['waiting'] = asyncio.ensure_future(_await_result(app, number, handle))
    return web.json_response({'accepted': handle.accepted, 'goal': nav2['goal']})


async def _await_result(app: web.Application, number: int, handle: Any) -> None:
    bridge, nav2 = app['bridge'], _nav2(app)
    pending = await bridge.run(handle.get_result_async)
    answer = await bridge.to_asyncio(pending)
    if nav2['goals'] != number:
        return
    # action_msgs/GoalStatus: 4 SUCCEEDED, 5 CANCELED, 6 ABORTED
    status = {4: 'succeeded', 5: 'canceled', 6: 'aborted'}.get(answer.status,
                                                               str(answer.status))
    nav2.update(status=status, handle=None, result={
        'error_code': answer.result.error_code, 'error_msg': answer.result.error_msg})


async def cancel_route(request: web.Request) -> web.Response:
    bridge, nav2 = request.app['bridge'], _nav2(request.app)
    handle = nav2['handle']
    if handle is None:
        return web.json_response({'canceled': False, 'status': nav2['status']})
    pending = await bridge.run(handle.cancel_goal_async)
    await bridge.to_asyncio(pending)
    return web.json_response({'canceled': True})


# ------------------------------------------------------------------ Navigation 2 panel

async def manage_route(request: web.Request) -> web.Response:
    try:
        body = await request.json()
        command = body.get('command') if isinstance(body, dict) else None
    except ValueError:
        command = None
    if command not in COMMANDS:
        raise web.HTTPBadRequest(text=f'command must be one of {", ".join(COMMANDS)}, got '
                                 f'{command!r}\n')
    from nav2_msgs.srv import ManageLifecycleNodes
    order = MANAGERS if command in ('startup', 'resume') else MANAGERS[::-1]
    bridge, answers = request.app['bridge'], {}
    for manager in order:
        try:
            response = await bridge.call_service(
                f'/{manager}/manage_nodes', 'nav2_msgs/srv/ManageLifecycleNodes',
                ManageLifecycleNodes.Request(command=COMMANDS[command]), SERVICE_WAIT * 6)
            answers[manager] = bool(response.success)
        except TimeoutError as error:
            answers[manager] = str(error)
    await _poll_states(request.app)
    return web.json_response({'command': command, 'success': answers,
                              'states': _nav2(request.app)['states']})


async def _poll_states(app: web.Application) -> None:
    from std_srvs.srv import Trigger
    nav2 = _nav2(app)
    for manager in MANAGERS:
        try:
            response = await app['bridge'].call_service(
                f'/{manager}/is_active', 'std_srvs/srv/Trigger', Trigger.Request(),
                SERVICE_WAIT)
            nav2['states'][manager] = 'active' if response.success else 'inactive'
        except TimeoutError:
            nav2['states'][manager] = 'unknown'


async def _poll_loop(app: web.Application) -> None:
    while True:
        await _poll_states(app)
        await asyncio.sleep(1.0)


async def state_route(request: web.Request) -> web.Response:
    nav2 = _nav2(request.app)
    if not nav2['polling']:
        nav2['polling'] = True
        request.app['rviz_nav2_poll'] = asyncio.ensure_future(_poll_loop(request.app))
    return web.json_response({
        'navigation': nav2['states'][MANAGERS[1]],
        'localization': nav2['states'][MANAGERS[0]], 'status': nav2['status'],
        'goal': nav2['goal'], 'goals': nav2['goals'], 'feedback': nav2['feedback'],
        'result': nav2['result']})


async def _stop_polling(app: web.Application) -> None:
    task = app.get('rviz_nav2_poll')
    if task is not None:
        task.cancel()


def add_routes(app: web.Application) -> None:
    app.router.add_routes([
        web.get('/api/rviz/particles', particles_route),
        web.post('/api/rviz/nav2/goal', goal_route),
        web.post('/api/rviz/nav2/cancel', cancel_route),
        web.post('/api/rviz/nav2/manage', manage_route),
        web.get('/api/rviz/nav2/state', state_route)])
    app.on_shutdown.append(_stop_polling)
