"""Contact rules (``P``): geoms that start inside each other.

MuJoCo finds the contacts itself (``mj_forward`` at ``qpos0`` and at each key), so only
pairs that can collide count: their ``contype``/``conaffinity`` match, they are not in
one body or a body and its parent, and no ``<exclude>`` keeps them apart. A contact
whose distance is below minus :data:`DEPTH` is a penetration the first step resolves
with a jolt.

One exception of MuJoCo's is not followed: MuJoCo lets a body collide with its parent
when the parent is welded to the world (a gripper's palm and fingers, alone in their
file). Once the part is mounted on anything that moves, as it is meant to be, MuJoCo
filters that pair like any parent and child; so does this rule (:func:`mounted_pair`).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from mjcf_model.tools.lint.findings import Finding, rule
from mjcf_model.tools.lint.keyframes import keys_writing
from mjcf_model.tools.lint.subject import Subject

if TYPE_CHECKING:
    import mujoco

__all__ = ["DEPTH", "mounted_pair", "penetrations"]

#: How deep geoms may overlap before it counts: a millimetre in a model in metres (MuJoCo
#: has no unit of its own; a model in centimetres is judged at a hundredth of one).
DEPTH = 1e-3


def penetrations(subject: Subject, key: int | None) -> list[tuple[float, int, int]]:
    """The deepest overlap of each pair of geoms in contact at ``key`` (``None``: ``qpos0``).

    Each as ``(depth, geom, geom)``, deepest first, only those deeper than :data:`DEPTH`.
    """
    import mujoco

    m = subject.physics
    data = mujoco.MjData(m)
    if key is None:
        mujoco.mj_resetData(m, data)
    else:
        mujoco.mj_resetDataKeyframe(m, data, key)
    mujoco.mj_forward(m, data)
    deepest: dict[tuple[int, int], float] = {}
    roots = _mounted_welds(m)
    for contact in data.contact[: data.ncon]:
        depth = -float(contact.dist)
        if depth <= DEPTH:
            continue
        pair = (int(min(contact.geom)), int(max(contact.geom)))
        bodies = (int(m.geom_bodyid[pair[0]]), int(m.geom_bodyid[pair[1]]))
        if mounted_pair(m, roots, *bodies):
            continue
        deepest[pair] = max(depth, deepest.get(pair, 0.0))
    return sorted(((depth, a, b) for (a, b), depth in deepest.items()), reverse=True)


def _mounted_welds(m: mujoco.MjModel) -> list[int]:
    """Each body's weld body, as if the bodies welded to the world were mounted on one that moves.

    A body MuJoCo welds to the world is welded to its own top body (the world's child
    above it) instead; the world stays itself.
    """
    welds = [int(w) for w in m.body_weldid]
    for body in range(1, m.nbody):
        if welds[body] == 0:
            top = body
            while int(m.body_parentid[top]) != 0:
                top = int(m.body_parentid[top])
            welds[body] = top
    return welds


def mounted_pair(m: mujoco.MjModel, welds: list[int], first: int, second: int) -> bool:
    """Whether MuJoCo filters two bodies as parent and child once their model is mounted.

    MuJoCo's own rule (``filterparent``): the weld body of one is the weld body of the
    other's weld body's parent; here with :func:`_mounted_welds`, so a part's top body
    welded to the world counts as a parent too. The world itself never does.
    """
    if first == 0 or second == 0:
        return False
    one, other = welds[first], welds[second]
    above_one = welds[int(m.body_parentid[one])]
    above_other = welds[int(m.body_parentid[other])]
    return one == above_other or other == above_one


def _message(subject: Subject, depth: float, a: int, b: int, where: str) -> str:
    return (
        f"geoms {subject.name('geom', a)} and {subject.name('geom', b)} overlap by "
        f"{depth:.3g} (in the model's unit of length; {depth * 1000:.3g} mm in metres) "
        f"{where}: the first step pushes them apart with a jolt; move them apart, or keep "
        "them from colliding (contype/conaffinity, <exclude>)"
    )


@rule(
    "P101",
    "penetration-at-qpos0",
    "warning",
    "two geoms that can collide overlap by more than a millimetre in the model's initial pose",
)
def penetration_at_qpos0(subject: Subject) -> Iterator[Finding]:
    """Geoms in contact and overlapping at ``qpos0``, as MuJoCo's collision detection sees them."""
    for depth, a, b in penetrations(subject, None):
        yield subject.finding("P101", ("geom", b), _message(subject, depth, a, b, "at qpos0"))


@rule(
    "P102",
    "penetration-at-key",
    "warning",
    "two geoms that can collide overlap by more than a millimetre at a key",
)
def penetration_at_key(subject: Subject) -> Iterator[Finding]:
    """Geoms in contact and overlapping at a key that writes ``qpos`` (or ``mpos``...)."""
    writing = sorted({*keys_writing(subject, "qpos"), *keys_writing(subject, "mpos")})
    for key in writing:
        for depth, a, b in penetrations(subject, key):
            where = f"at key {subject.name('key', key)}"
            yield subject.finding("P102", ("key", key), _message(subject, depth, a, b, where))
