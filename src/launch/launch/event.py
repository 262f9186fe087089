"""Event: something that happened during a launch, handed to the matching event handlers."""


class Event:
    """Base class of every event; `name` says which kind it is."""

    name = 'launch.Event'

    def __repr__(self) -> str:
        return f'{type(self).__name__}()'
