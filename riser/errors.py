"""Errors raised for bad input, shared by every package.

A :class:`SceneError` always carries the file name and the key path of the
offending entry, so the command line can print it as one line, e.g.::

    scene.toml: segments[2].length: must be > 0, got -5
"""

from __future__ import annotations


#: the longest file name, key or message a one-line error echoes [characters]; what a
#: user typed is shown whole up to this, then cut with its length said
ECHO_LIMIT = 300


def one_line(text: str, limit: int = ECHO_LIMIT) -> str:
    """``text`` fit for one line of a terminal: control characters (a CR or LF from a
    script saved with CRLF line endings, a NUL) shown as escapes (\\r, \\n, \\x00), and
    cut to ``limit`` characters with the full length said (a 5,000-character path or value
    echoed in full made a "one-line" refusal of pages)."""
    text = str(text)
    if any(ord(c) < 0x20 or ord(c) == 0x7F for c in text):
        text = "".join(repr(c)[1:-1] if (ord(c) < 0x20 or ord(c) == 0x7F) else c
                       for c in text)
    if len(text) > limit:
        text = f"{text[:limit]}... ({len(text):,} characters)"
    return text


class SceneError(ValueError):
    """Invalid scene input: names the file, the key path and what is allowed. The three
    parts are echoed on one line (:func:`one_line`; the message may be longer than the
    name, up to three times the echo limit)."""

    def __init__(self, source: str, key: str, message: str):
        self.source = source
        self.key = key
        self.message = message
        src, k = one_line(source), one_line(key)
        msg = one_line(message, 3 * ECHO_LIMIT)
        super().__init__(f"{src}: {k}: {msg}" if key else f"{src}: {msg}")


class UnsupportedSceneError(ValueError):
    """A valid scene that a particular solver cannot handle (e.g. 3D current for the BVP)."""


class SolveFailed(RuntimeError):
    """A solve that a larger job depends on did not converge (e.g. the BVP a fixed-ends
    conversion starts from, or one method of a comparison). ``method`` names the method
    and ``status`` (a :class:`riser.results.result.Status`) says how it ended."""

    def __init__(self, method: str, status, message: str):
        self.method = method
        self.status = status
        super().__init__(message)
