"""ProcessStarted: a process has been started."""

from launch.events.process.running_process_event import RunningProcessEvent


class ProcessStarted(RunningProcessEvent):
    name = 'launch.events.process.ProcessStarted'
