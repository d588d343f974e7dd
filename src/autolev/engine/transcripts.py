"""The answer `autolev transcript` keeps: its text, importing neither numpy nor sympy
(a warm transcript is read back and printed, nothing more)."""
from __future__ import annotations

from dataclasses import dataclass

from .reading import ReadSet


@dataclass
class KeptTranscript:
    """The text of `autolev transcript FILE`: the same files read give the same text."""

    reads: ReadSet              # every file read to make it, as read
    text: str
