"""Exceptions raised by the pipeline.

``InputError`` is the one a user can act on (bad file, wrong units, empty drawing...). The
Processing layer turns it into ``QgsProcessingException`` with the same message.
"""


class Cad2OsmagError(Exception):
    """Base class of every error the pipeline raises on purpose."""


class InputError(Cad2OsmagError, ValueError):
    """The input cannot be processed; the message says what is wrong and what to do."""


class Canceled(Cad2OsmagError):
    """The user canceled the operation (raised when ``Progress.is_canceled()`` is true)."""
