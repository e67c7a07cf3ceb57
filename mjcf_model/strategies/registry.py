"""What a model being drawn declares, for the elements and sections that refer to it."""

from __future__ import annotations

import attrs


class _Names:
    """Hands out names unique per namespace (``body0``, ``geom3``...)."""

    def __init__(self) -> None:
        self.issued: dict[str, int] = {}

    def __call__(self, namespace: str) -> str:
        number = self.issued.get(namespace, 0)
        self.issued[namespace] = number + 1
        return f"{namespace}{number}"

    def most(self) -> int:
        """The most names handed out in one namespace."""
        return max(self.issued.values(), default=0)


@attrs.define
class _Registry:
    """The names a drawn model declares, by what may refer to them.

    Elements inside a ``<replicate>`` are left out: MuJoCo suffixes their names,
    so nothing refers to them by the name written.
    """

    names: _Names = attrs.field(factory=_Names)
    #: The model's ``<compiler angle>``: ``degree`` (MuJoCo's default) or ``radian``.
    angle: str = "degree"
    scalar_joints: list[str] = attrs.field(factory=list)
    bodies: list[str] = attrs.field(factory=list)
    mocap_bodies: list[str] = attrs.field(factory=list)
    geoms: list[str] = attrs.field(factory=list)
    #: Named spheres and cylinders, which a spatial tendon can wrap around.
    wrapping_geoms: list[str] = attrs.field(factory=list)
    sites: list[str] = attrs.field(factory=list)
    materials: list[str] = attrs.field(factory=list)
    meshes: list[str] = attrs.field(factory=list)
    classes: list[str] = attrs.field(factory=list)
    tendons: list[str] = attrs.field(factory=list)
    #: Whether the model has a ``<replicate>`` (MuJoCo 3.9 copies keyframes per copy).
    replicates: bool = False
