"""Load a launch test module: its test description(s) and its active and post-shutdown tests."""

from __future__ import annotations

import functools
import inspect
import unittest
from collections.abc import Callable, Iterator
from typing import Any

from launch_testing.actions import ReadyToTest

DEFAULT_READY_TIMEOUT = 15.0  # seconds the runner waits for ReadyToTest (upstream's default)


def _ready_actions(entities: list[Any]) -> Iterator[ReadyToTest]:
    """Every ReadyToTest in a launch description, however deeply nested."""
    for entity in entities:
        if isinstance(entity, ReadyToTest):
            yield entity
        yield from _ready_actions(entity.describe_sub_entities())
        for _, sub_entities in entity.describe_conditional_sub_entities():
            yield from _ready_actions(list(sub_entities))


class TestRun:
    """One launch of the description (a parametrized description gives several)."""

    __test__ = False  # not a pytest test class

    def __init__(self, name: str, test_description_function: Callable[..., Any],
                 param_args: dict[str, Any], pre_shutdown_tests: unittest.TestSuite,
                 post_shutdown_tests: unittest.TestSuite) -> None:
        self.name = name
        if not hasattr(test_description_function, '__markers__'):
            test_description_function.__markers__ = {}  # type: ignore[attr-defined]
        self._test_description_function = test_description_function
        self.param_args = param_args
        self.pre_shutdown_tests = pre_shutdown_tests
        self.post_shutdown_tests = post_shutdown_tests
        self.timeout = float(getattr(test_description_function,
                                     '__ready_to_test_action_timeout__', DEFAULT_READY_TIMEOUT))
        if param_args:  # test names say which parameters they ran with: test_x[a, 1]
            for case in self.all_cases():
                method = getattr(case, case._testMethodName)
                renamed = case._testMethodName + self._format_params()
                case._testMethodName = renamed
                setattr(case, renamed, method)

    @property
    def markers(self) -> dict[str, Any]:
        return self._test_description_function.__markers__  # type: ignore[attr-defined]

    def normalized_test_description(self, ready_fn: Callable[[], None]
                                    ) -> tuple[Any, dict[str, Any]]:
        """(launch description, test context), with ready_fn hooked to its ReadyToTest."""
        function = self._test_description_function
        try:
            result = function(ready_fn=ready_fn) if 'ready_fn' in _parameters(function) \
                else function()
        except TypeError:
            raise
        description, context = result if isinstance(result, tuple) else (result, {})
        ready = list(_ready_actions(description.entities))
        if not ready:
            raise Exception('generate_test_description functions must return a '
                            'LaunchDescription containing a ReadyToTest action')
        ready[0]._add_callback(ready_fn)
        return description, dict(context)

    def get_launch_description(self) -> Any:
        """The description alone, to inspect (e.g. its arguments), not to launch."""
        return self.normalized_test_description(ready_fn=lambda: None)[0]

    def bind(self, tests: unittest.TestSuite, injected_attributes: dict[str, Any],
             injected_args: dict[str, Any]) -> None:
        """Give the tests `self.<name>` attributes and matching method arguments."""
        for cls in _test_classes(tests):
            for name, value in injected_attributes.items():
                setattr(cls, name, value)
            for hook in ('setUpClass', 'tearDownClass'):
                setattr(cls, hook, _bind_matching(getattr(cls, hook), injected_args))
        for case in _tests(tests):
            setattr(case, case._testMethodName,
                    _bind_matching(getattr(case, case._testMethodName), injected_args))
            case.setUp = _bind_matching(case.setUp, injected_args)
            case.tearDown = _bind_matching(case.tearDown, injected_args)

    def all_cases(self) -> Iterator[unittest.TestCase]:
        yield from _tests(self.pre_shutdown_tests)
        yield from _tests(self.post_shutdown_tests)

    def __str__(self) -> str:
        return self.name + self._format_params()

    def _format_params(self) -> str:
        if not self.param_args:
            return ''
        return '[' + ', '.join(str(value) for value in self.param_args.values()) + ']'


def LoadTestsFromPythonModule(module: Any, *, name: str = 'launch_tests'
                              ) -> list[TestRun]:
    """A TestRun per launch: one, or one per parameter set of @launch_testing.parametrize."""
    function = module.generate_test_description
    runs = function() if getattr(function, '__parametrized__', False) else [(function, {})]
    return [TestRun(name, description, dict(args), _load(module, post_shutdown=False),
                    _load(module, post_shutdown=True)) for description, args in runs]


def _load(module: Any, *, post_shutdown: bool) -> unittest.TestSuite:
    """The module's TestCases of one kind, each class subclassed so runs do not share state."""

    class Loader(unittest.TestLoader):
        def loadTestsFromTestCase(self, testCaseClass: type) -> unittest.TestSuite:
            if getattr(testCaseClass, '__post_shutdown_test__', False) != post_shutdown:
                return self.suiteClass()
            fresh = type(testCaseClass.__name__, (testCaseClass,),
                         {'__module__': testCaseClass.__module__})
            return super().loadTestsFromTestCase(fresh)

    suite = Loader().loadTestsFromModule(module)
    for inner in _suites(suite):
        inner._removeTestAtIndex = lambda *args, **kwargs: None  # keep cases for the report
    return suite


def _parameters(function: Callable[..., Any]) -> set[str]:
    try:
        return set(inspect.signature(function).parameters)
    except (TypeError, ValueError):
        return set()


def _bind_matching(function: Callable[..., Any], candidates: dict[str, Any]
                   ) -> Callable[..., Any]:
    """function with the candidates whose names are among its parameters bound."""
    wanted = _parameters(function)
    matching = {key: value for key, value in candidates.items() if key in wanted}
    if not matching:
        return function
    bound = functools.partial(function, **matching)
    functools.update_wrapper(bound, function)
    return bound


def _suites(suite: Any) -> Iterator[unittest.TestSuite]:
    if isinstance(suite, unittest.TestSuite):
        yield suite
        for item in suite:
            yield from _suites(item)


def _tests(suite: Any) -> Iterator[unittest.TestCase]:
    if isinstance(suite, unittest.TestSuite):
        for item in suite:
            yield from _tests(item)
    else:
        yield suite


def _test_classes(suite: Any) -> list[type]:
    classes: list[type] = []
    for case in _tests(suite):
        if type(case) not in classes:
            classes.append(type(case))
    return classes
