"""The package's exceptions, raised by its native door as well as its Python side."""


class Error(OSError):
    """A run that could not be done: the message names the cause (an OSError)."""


class Cancelled(Exception):
    """The progress callable returned False: the run stopped, nothing written."""


Error.__module__ = Cancelled.__module__ = "terrain_sketch"
