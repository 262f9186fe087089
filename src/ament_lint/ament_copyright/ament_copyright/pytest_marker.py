"""Registers the `copyright` marker the generated test_copyright.py uses."""


def pytest_configure(config) -> None:
    config.addinivalue_line('markers', 'copyright: marks tests checking for copyright notices')
