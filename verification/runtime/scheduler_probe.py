"""A bounded look at a Dask scheduler's address before a client connects to it.

``distributed.Client(address, timeout=...)`` bounds the TCP connection but not what comes
after: its comm handshake reads the peer's first message with no timeout, and reads it
by trusting the 8-byte length that starts it (``distributed.comm.tcp.TCP.read``). So an
address that is not a scheduler made ``riser-verify sweep --scheduler`` hang for ever (a
server that accepts and says nothing: the dashboard's port 8787, an HTTP server) or fail
with ``MemoryError: Unable to allocate 3.07 EiB`` (an HTTP reply, whose first 8 bytes
``HTTP/1.1`` read as a length).

:func:`probe` does that handshake itself with a deadline and a bound on every length:
it connects (a plain socket, ``timeout`` seconds in all), sends this process's handshake
(so that an HTTP server answers at once, with bytes that are not one), reads the
scheduler's (a scheduler sends it at once on accepting a connection: ``Comm`` framing, an
8-byte length, the frame count and lengths, then a msgpack map with ``python`` and
``pickle-protocol``), decodes it with msgpack alone (no pickle, no object hook) and
closes: the scheduler has seen a complete exchange. Outcomes, as :class:`ProbeFailed`:

- the address cannot be reached (refused, no route, unknown host, no connection within
  the timeout): ``bad_input`` False, exit 1: a valid address whose scheduler is not up
  (yet);
- something answers but is not a Dask scheduler (silent, closes at once, sends bytes that
  are not a handshake): ``bad_input`` True, exit 2: the address is wrong.

Imports nothing of ``verification`` (and ``msgpack``, which ``distributed`` requires,
only when a handshake arrived).
"""

from __future__ import annotations

import pickle
import socket
import struct
import sys
import time

#: seconds the probe may take in all (connection and handshake); a scheduler answers in
#: milliseconds on a LAN
PROBE_TIMEOUT_S = 5.0
#: the largest handshake accepted [bytes]; a real one is ~100 bytes
MAX_HANDSHAKE_BYTES = 64 * 1024
#: the most frames a handshake may declare (a real one has 1)
MAX_FRAMES = 16
_Q = struct.Struct("Q")          # distributed's framing: native unsigned 64-bit


class ProbeFailed(Exception):
    """The address is not a usable Dask scheduler: the message (one line) and whether it
    is bad input (something answered that is not a scheduler: exit 2) or an unreachable
    address (exit 1)."""

    def __init__(self, message: str, bad_input: bool):
        super().__init__(message)
        self.bad_input = bad_input


def _recv(sock: socket.socket, n: int, deadline: float) -> bytes:
    """Exactly ``n`` bytes, or fewer when the peer closed or the deadline passed."""
    buf = bytearray()
    while len(buf) < n:
        left = deadline - time.monotonic()
        if left <= 0:
            break
        sock.settimeout(left)
        try:
            chunk = sock.recv(min(n - len(buf), 65536))
        except (socket.timeout, TimeoutError):
            break
        except OSError:                          # reset by the peer
            break
        if not chunk:
            break
        buf += chunk
    return bytes(buf)


def _shown(data: bytes) -> str:
    """The first bytes of a reply, for the message."""
    return repr(data[:16]) + ("..." if len(data) > 16 else "")


def _decode(body: bytes) -> dict | None:
    """The handshake map of a message body (frame count, frame lengths, frames), or None
    when the body is not one."""
    if len(body) < 2 * _Q.size:
        return None
    (count,) = _Q.unpack_from(body, 0)
    if not 1 <= count <= MAX_FRAMES or len(body) < _Q.size * (1 + count):
        return None
    lengths = struct.unpack_from(f"{count}Q", body, _Q.size)
    start = _Q.size * (1 + count)
    if lengths[0] > len(body) - start:
        return None
    import msgpack                               # a dependency of distributed
    try:
        msg = msgpack.unpackb(body[start:start + lengths[0]], raw=False, use_list=False,
                              strict_map_key=False)
    except Exception:                            # noqa: BLE001 - any garbage: not a handshake
        return None
    if not isinstance(msg, dict) or "pickle-protocol" not in msg or "python" not in msg:
        return None
    return msg


def _handshake() -> bytes:
    """This process's comm handshake as ``distributed.comm.tcp.TCP.write`` frames it: the
    message length, the frame count and length, the msgpack map of
    ``Comm.handshake_info``."""
    import msgpack                               # a dependency of distributed
    frame = msgpack.packb({"compression": None, "python": tuple(sys.version_info)[:3],
                           "pickle-protocol": pickle.HIGHEST_PROTOCOL}, use_bin_type=True)
    body = _Q.pack(1) + _Q.pack(len(frame)) + frame
    return _Q.pack(len(body)) + body


def probe(address: str, host: str, port: int, timeout: float = PROBE_TIMEOUT_S,
          handshake: bool = True) -> dict | None:
    """Connect to ``host:port`` (the scheduler ``address``, named in messages) and, with
    ``handshake`` (tcp://), read and answer its comm handshake, all within ``timeout``
    seconds; returns the scheduler's handshake map (None without ``handshake``). Raises
    :class:`ProbeFailed`."""
    deadline = time.monotonic() + timeout
    where = f"--scheduler {address}"
    advice = "start one with `dask scheduler` and workers with `dask worker ADDRESS`"
    try:
        sock = socket.create_connection((host, port), timeout=timeout)
    except socket.gaierror as exc:
        raise ProbeFailed(f"{where}: the scheduler does not answer: unknown host {host!r} "
                          f"({exc.strerror or exc}); {advice}", False) from None
    except (socket.timeout, TimeoutError):
        raise ProbeFailed(f"{where}: the scheduler does not answer within {timeout:g} s "
                          f"(no connection); {advice}", False) from None
    except OSError as exc:
        raise ProbeFailed(f"{where}: the scheduler does not answer within {timeout:g} s "
                          f"({type(exc).__name__}: {exc.strerror or exc}); {advice}",
                          False) from None
    with sock:
        if not handshake:
            return None
        not_one = f"{where}: not a Dask scheduler: it accepts connections but"
        try:                                     # ours first: an HTTP server answers it
            sock.settimeout(max(deadline - time.monotonic(), 0.01))
            sock.sendall(_handshake())
        except OSError:
            pass                                 # said by what it (does not) send
        head = _recv(sock, _Q.size, deadline)
        if not head:
            closed = time.monotonic() < deadline
            raise ProbeFailed(
                f"{not_one} {'closed the connection without' if closed else 'sent no'} "
                f"Dask handshake{'' if closed else f' within {timeout:g} s'} (a scheduler "
                "sends one at once; `dask scheduler` prints its address, tcp://HOST:8786 "
                "by default; 8787 is its dashboard)", True)
        (size,) = _Q.unpack(head) if len(head) == _Q.size else (0,)
        if not 2 * _Q.size <= size <= MAX_HANDSHAKE_BYTES:
            raise ProbeFailed(f"{not_one} answered {_shown(head)}, not a Dask handshake "
                              "(tcp://HOST:PORT of `dask scheduler`, 8786 by default)", True)
        body = _recv(sock, size, deadline)
        msg = _decode(body) if len(body) == size else None
        if msg is None:
            raise ProbeFailed(f"{not_one} answered {_shown(head + body)}, not a Dask "
                              "handshake (tcp://HOST:PORT of `dask scheduler`, 8786 by "
                              "default)", True)
        return msg
