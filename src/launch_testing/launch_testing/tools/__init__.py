"""launch_testing.tools: output matching and filters, and processes started mid-test."""

from launch_testing.tools.output import (
    basic_output_filter,
    expect_output,
    expected_output_from_file,
)
from launch_testing.tools.process import ProcessProxy, launch_process
from launch_testing.tools.text import build_line_match, build_text_match, normalize_lineseps

__all__ = ['ProcessProxy', 'basic_output_filter', 'build_line_match', 'build_text_match',
           'expect_output', 'expected_output_from_file', 'launch_process', 'normalize_lineseps']
