"""Progress reporting and cancellation, independent of QGIS.

Pipeline functions take an optional ``progress`` argument. The Processing provider passes an adapter
around ``QgsProcessingFeedback``; tests and scripts pass nothing (``NullProgress``) or a
``RecordingProgress`` to assert on the messages.
"""
from __future__ import annotations

from typing import List, Optional, Tuple

from .errors import Canceled


class Progress:
    """Interface. ``percent`` is 0..100 for the whole call that received this object."""

    def set_percent(self, percent: float) -> None:  # pragma: no cover - interface
        pass

    def info(self, message: str) -> None:  # pragma: no cover - interface
        pass

    def warning(self, message: str) -> None:  # pragma: no cover - interface
        pass

    def is_canceled(self) -> bool:
        return False

    # helpers -----------------------------------------------------------------
    def check(self) -> None:
        """Raise ``Canceled`` if the user asked to stop."""
        if self.is_canceled():
            raise Canceled("canceled by the user")

    def step(self, percent: float, message: Optional[str] = None) -> None:
        """Check for cancel, report ``percent`` and optionally log ``message``."""
        self.check()
        self.set_percent(percent)
        if message:
            self.info(message)

    def sub(self, start: float, end: float) -> "Progress":
        """A progress that maps 0..100 onto ``start``..``end`` of this one."""
        return _SubProgress(self, start, end)


class NullProgress(Progress):
    pass


class RecordingProgress(Progress):
    """Keeps everything it is told; handy in tests."""

    def __init__(self, cancel_after: Optional[int] = None):
        self.percents: List[float] = []
        self.messages: List[Tuple[str, str]] = []
        self._cancel_after = cancel_after
        self._checks = 0

    def set_percent(self, percent: float) -> None:
        self.percents.append(float(percent))

    def info(self, message: str) -> None:
        self.messages.append(("info", message))

    def warning(self, message: str) -> None:
        self.messages.append(("warning", message))

    def is_canceled(self) -> bool:
        self._checks += 1
        return self._cancel_after is not None and self._checks > self._cancel_after

    def text(self) -> str:
        return "\n".join(m for _, m in self.messages)


class _SubProgress(Progress):
    def __init__(self, parent: Progress, start: float, end: float):
        self._p, self._a, self._b = parent, float(start), float(end)

    def set_percent(self, percent: float) -> None:
        self._p.set_percent(self._a + (self._b - self._a) * max(0.0, min(100.0, percent)) / 100.0)

    def info(self, message: str) -> None:
        self._p.info(message)

    def warning(self, message: str) -> None:
        self._p.warning(message)

    def is_canceled(self) -> bool:
        return self._p.is_canceled()


def ensure(progress: Optional[Progress]) -> Progress:
    return progress if progress is not None else NullProgress()
