"""launch_testing.event_handlers: event handlers for launch tests."""

from launch_testing.event_handlers.stdout_ready_listener import StdoutReadyListener

__all__ = ['StdoutReadyListener']
