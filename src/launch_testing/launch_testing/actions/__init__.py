"""launch_testing.actions: ReadyToTest (upstream's GTest/PyTest actions are not provided)."""

from launch_testing.actions.ready import ReadyToTest

__all__ = ['ReadyToTest']
