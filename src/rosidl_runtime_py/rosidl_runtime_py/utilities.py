"""Interfaces by their full name: 'pkg/msg/Name' (or 'pkg/Name', the kind implied)."""

from __future__ import annotations

from typing import Any

from rosidl_parser.definition import NamespacedType

from rosidl_runtime_py.import_message import import_message_from_namespaced_type


def get_interface(identifier: str) -> Any:
    """The message, service or action class 'pkg/kind/Name' names."""
    return import_message_from_namespaced_type(get_namespaced_type(identifier))


def get_message(identifier: str) -> Any:
    return _get_checked(identifier, 'msg', is_message, 'a message')


def get_service(identifier: str) -> Any:
    return _get_checked(identifier, 'srv', is_service, 'a service')


def get_action(identifier: str) -> Any:
    return _get_checked(identifier, 'action', is_action, 'an action')


def _get_checked(identifier: str, kind: str, check: Any, article_kind: str) -> Any:
    interface = import_message_from_namespaced_type(_namespaced_type(identifier, kind))
    if not check(interface):
        raise ValueError(f"Expected the full name of {article_kind}, got '{identifier}'")
    return interface


def get_namespaced_type(identifier: str) -> NamespacedType:
    return _namespaced_type(identifier)


def get_message_namespaced_type(identifier: str) -> NamespacedType:
    return _namespaced_type(identifier, 'msg')


def get_service_namespaced_type(identifier: str) -> NamespacedType:
    return _namespaced_type(identifier, 'srv')


def get_action_namespaced_type(identifier: str) -> NamespacedType:
    return _namespaced_type(identifier, 'action')


def is_message(interface: Any) -> bool:
    return hasattr(interface, 'SLOT_TYPES')


def is_service(interface: Any) -> bool:
    return hasattr(interface, 'Request') and hasattr(interface, 'Response')


def is_action(interface: Any) -> bool:
    return all(hasattr(interface, part) for part in ('Goal', 'Result', 'Feedback'))


def _namespaced_type(identifier: str, default_namespace: str | None = None) -> NamespacedType:
    """'pkg/kind/Name' -> (['pkg', 'kind'], 'Name'); 'pkg/Name' gets the default kind."""
    *namespaces, name = identifier.split('/')
    if len(namespaces) == 1 and default_namespace is not None:
        namespaces.append(default_namespace)
    return NamespacedType(namespaces, name)
