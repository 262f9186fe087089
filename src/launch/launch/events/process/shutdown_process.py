"""ShutdownProcess: stop the matching processes as a launch shutdown would."""

from launch.events.process.process_targeted_event import ProcessTargetedEvent


class ShutdownProcess(ProcessTargetedEvent):
    name = 'launch.events.process.ShutdownProcess'
