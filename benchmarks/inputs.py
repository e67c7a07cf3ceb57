"""The inputs every contender shares: the corpus files and synthetic models."""

from __future__ import annotations

import functools
import importlib.util
from pathlib import Path

__all__ = ["compiling_corpus", "package_dir", "synthetic_xml"]


def package_dir(name: str) -> Path | None:
    """Where an installed package lives, without importing it (``None`` when absent)."""
    spec = importlib.util.find_spec(name)
    if spec is None or spec.origin is None:
        return None
    return Path(spec.origin).parent


@functools.cache
def compiling_corpus(most: int | None = None) -> tuple[Path, ...]:
    """The XML files of the installed robosuite and dm_control wheels that MuJoCo compiles.

    ``most``: only the first that many (a tiny run need not compile the whole corpus).
    """
    import mujoco

    files: list[Path] = []
    for package in ("robosuite", "dm_control"):
        folder = package_dir(package)
        if folder is not None:
            files.extend(sorted(folder.rglob("*.xml")))
    compiling: list[Path] = []
    for path in files:
        if len(compiling) == most:
            break
        try:
            mujoco.MjModel.from_xml_path(str(path))
        except ValueError:
            continue
        compiling.append(path)
    return tuple(compiling)


def _body(index: int) -> str:
    return (
        f'<body name="b{index}" pos="0.1 0 0.05"><joint name="j{index}" type="hinge" '
        f'axis="0 0 1" range="-1 1"/><geom name="g{index}" type="capsule" size="0.02 0.05" '
        f'rgba="0.5 0.5 0.5 1"/><site name="s{index}" pos="0 0 0.01"/>'
    )


def synthetic_xml(bodies: int, shape: str) -> str:
    """A model of ``bodies`` bodies, each with a joint, a geom and a site.

    ``shape`` is ``"deep"`` (chains of 50 nested bodies) or ``"wide"`` (all in the world).
    """
    depth = 50 if shape == "deep" else 1
    parts = ["<mujoco model='synthetic'><worldbody>"]
    index = 0
    while index < bodies:
        chain = min(depth, bodies - index)
        parts.extend(_body(index + k) for k in range(chain))
        parts.append("</body>" * chain)
        index += chain
    parts.append("</worldbody><actuator>")
    parts.extend(f'<motor name="m{i}" joint="j{i}" gear="10"/>' for i in range(0, bodies, 10))
    parts.append("</actuator></mujoco>")
    return "".join(parts)
