"""InvalidLaunchFileError: a launch file could not be loaded; says what each loader hit."""

from __future__ import annotations


class InvalidLaunchFileError(Exception):
    def __init__(self, extension: str = '', *,
                 likely_errors: list[BaseException] | None = None) -> None:
        super().__init__()
        self._extension = extension
        self._likely_errors = likely_errors
        if not extension or not likely_errors:
            self._error_message = ('The launch file may have a syntax error, or its format is '
                                   'unknown')
            return
        if len(likely_errors) == 1:
            # One cause: one line (upstream puts it on a line of its own).
            error = likely_errors[0]
            self._error_message = (f'Caught exception when trying to load file of format '
                                   f'[{extension}]: {type(error).__name__}: {error}')
        else:
            lines = [f'Caught multiple exceptions when trying to load file of format '
                     f'[{extension}]:']
            lines += [f' - {type(error).__name__}: {error}' for error in likely_errors]
            self._error_message = '\n'.join(lines)
        self.__cause__ = likely_errors[0]

    def __str__(self) -> str:
        return self._error_message
