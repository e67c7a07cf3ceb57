"""Binary MuJoCo skin files (``.skn``) written for tests."""

from __future__ import annotations

import struct
from pathlib import Path

from mjcf_model.values import format_float

__all__ = ["skin_file"]


def skin_file(path: Path, bodies: tuple[str, ...]) -> Path:
    """Write a binary skin of one triangle whose vertex ``i`` is bound to ``bodies[i]``.

    Bone ``i`` is bound at ``(0.01 i, 0.02, 0.03)``, unrotated, so both its
    vertices and its bind positions are lengths a scaling must change.
    """
    data = struct.pack("<4i", 3, 0, 1, len(bodies))
    data += struct.pack("<9f", 0, 0, 0, 0.1, 0, 0, 0, 0.1, 0)
    data += struct.pack("<3i", 0, 1, 2)
    for index, body in enumerate(bodies):
        bind = struct.pack("<7f", 0.01 * index, 0.02, 0.03, 1, 0, 0, 0)
        data += body.encode().ljust(40, b"\0") + bind
        data += struct.pack("<i", 1) + struct.pack("<i", index) + struct.pack("<f", 1)
    path.write_bytes(data)
    return path


def _skin_model(vertices: list[float], name: str | None = "skin") -> str:
    count = len(vertices) // 3
    named = f' name="{name}"' if name else ""
    numbers = " ".join(format_float(v) for v in vertices)
    ids = " ".join(str(i) for i in range(count))
    return (
        '<mujoco><worldbody><body name="b"><geom size="0.1"/></body></worldbody><asset>'
        f'<skin{named} vertex="{numbers}" face="0 1 2">'
        f'<bone body="b" bindpos="0.1 0.2 0.3" bindquat="1 0 0 0" vertid="{ids}" '
        f'vertweight="{" ".join(["1"] * count)}"/></skin></asset></mujoco>'
    )
