"""launch_testing's pytest plugin: pytest runs launch test files as it runs any test file."""
