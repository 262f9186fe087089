"""Event: something that happened during a launch, handed to the matching event handlers."""


class Event:
    name = 'launch.event.Event'
