"""launch_testing.tools: text matching used by the output asserts."""

from launch_testing.tools.text import build_text_match, normalize_lineseps

__all__ = ['build_text_match', 'normalize_lineseps']
