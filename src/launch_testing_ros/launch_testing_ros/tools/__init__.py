"""launch_testing_ros.tools: output filters aware of the RMW implementation."""

from launch_testing_ros.tools.output import basic_output_filter, get_rmw_output_filter

__all__ = ['basic_output_filter', 'get_rmw_output_filter']
