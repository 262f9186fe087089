"""launch_xml: the XML front end of launch (`<launch><node pkg=... exec=.../></launch>`)."""

from launch_xml.parser import Parser

__all__ = ['Parser']
