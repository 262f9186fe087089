# Run every registered linter hook, except those named in AMENT_LINT_AUTO_EXCLUDE.
ament_execute_extensions(ament_lint_auto EXCLUDE "${AMENT_LINT_AUTO_EXCLUDE}")
