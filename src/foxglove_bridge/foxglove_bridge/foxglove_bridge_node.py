"""`ros2 run foxglove_bridge foxglove_bridge`: Foxglove and Lichtblick on one WebSocket port."""

from __future__ import annotations

import asyncio
import threading
import time

from node_runtime.spinning import ros_session, spin_until_stopped
from rclpy.executors import SingleThreadedExecutor

from foxglove_bridge.front import Front
from foxglove_bridge.origin_policy import OriginPolicy
from foxglove_bridge.protocol_v1 import V1Server
from foxglove_bridge.ros_bridge import FoxgloveBridge
from foxglove_bridge.sdk_server import SdkServer

VERSION = '0.1.0'


async def serve(node: FoxgloveBridge, stop: threading.Event) -> None:
    session_id = str(time.time_ns())
    v1 = V1Server(node, session_id)
    v1_server = await v1.start()
    sdk = SdkServer(node, session_id)
    node.frontends += [v1, sdk]
    settings = node.settings
    try:
        policy = OriginPolicy(settings.origin_allowlist, settings.address)
        front = await Front(sdk.port, v1.port, policy, node.get_logger().warn).start(
            settings.address, settings.port)
    except OSError as error:
        node.get_logger().error(f'Failed to listen on {settings.address}:{settings.port}: '
                                f'{error.strerror}')
        sdk.stop()
        stop.set()
        return
    port = front.sockets[0].getsockname()[1]
    node.get_logger().info(f'Server listening on port {port}')
    try:
        while not stop.is_set():
            await asyncio.sleep(0.1)
    finally:
        front.close()
        v1_server.close()
        node.frontends.clear()
        sdk.stop()


def main(args: list[str] | None = None) -> None:
    with ros_session(args) as stop:
        node = FoxgloveBridge()
        node.get_logger().info(f'Starting foxglove_bridge (jazzy, {VERSION})')
        spinner = threading.Thread(target=spin_until_stopped,
                                   args=(node, stop, SingleThreadedExecutor()), daemon=True)
        spinner.start()
        asyncio.run(serve(node, stop))
        stop.set()
        spinner.join(timeout=5)


if __name__ == '__main__':
    main()
