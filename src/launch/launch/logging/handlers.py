"""launch.logging.handlers: the handler classes launch's log configuration builds on."""

from logging import FileHandler, Handler, StreamHandler

__all__ = ['FileHandler', 'Handler', 'StreamHandler']
