"""Keeping a child's masses and inertias under a parent's inertia settings.

When the two ``<compiler>`` sections read inertia differently (``inertiafromgeom``,
``boundmass``, ``boundinertia``, ``balanceinertia``, ``inertiagrouprange``,
``settotalmass``), the child is compiled alone and every body gets an explicit
``<inertial>`` with what MuJoCo computed; the result is compiled again under the
parent's settings to check that nothing moved. Used by
:func:`mjcf_model.transforms.composition.conventions.in_conventions`.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import numpy.typing as npt

from mjcf_model.bridge.compiling import compiled
from mjcf_model.errors import MjcfError, MjcfValueError
from mjcf_model.nodes.base import AnyElement, attribute_items, get_attribute, with_attributes
from mjcf_model.nodes.body import Inertial
from mjcf_model.nodes.compiler import Compiler
from mjcf_model.nodes.root import Mujoco
from mjcf_model.transforms.composition.compiler_settings import (
    CONVERTED_SETTINGS,
    INERTIA_SETTINGS,
    PATH_SETTINGS,
    Settings,
)
from mjcf_model.transforms.naming.generated_names import copy_suffix
from mjcf_model.transforms.naming.renaming import declared_names
from mjcf_model.tree.traversal import map_elements, with_children
from mjcf_model.values import Value

__all__ = ["inertia_kept"]

Changes = dict[str, Value | None]
#: Compiled body arrays by ``MjModel`` field name.
Arrays = dict[str, npt.NDArray[np.float64]]

#: Settings under which the inertia of every body of a tree is compared.
_NEUTRAL = {"fusestatic": "false", "discardvisual": "false", "alignfree": "false"}
_INERTIA_FIELDS = ("body_mass", "body_ipos", "body_iquat", "body_inertia")
#: The start of the names given to unnamed bodies while their inertia is compiled.
_MADE_UP = "mjcf_model_conventions_"


def _variant(model: Mujoco, settings: Settings) -> Mujoco:
    """``model`` under one ``<compiler>``: its paths, ``settings``, no body fused or aligned."""
    sections = [e for e in model.elements if e.tag == "compiler"]
    written: Changes = {k: v for k, v in settings.items() if k in CONVERTED_SETTINGS}
    for section in sections:
        written.update((k, v) for k, v in attribute_items(section) if k in PATH_SETTINGS)
    written.update(_NEUTRAL)
    # no <lengthrange>: it is model-wide (the parent's holds) and inertias do not read it
    compiler = with_attributes(Compiler(), written)

    def unaligned(
        element: AnyElement, key: str | None, ancestors: Sequence[AnyElement]
    ) -> AnyElement:
        return with_attributes(element, {"align": "false"}) if key == "body/freejoint" else element

    rest = [c for c in model.children if getattr(c, "tag", None) != "compiler"]
    return map_elements(unaligned, with_children(model, [compiler, *rest]))


def _named_bodies(model: Mujoco, taken: frozenset[str]) -> tuple[Mujoco, list[str]]:
    """``model`` with a made-up name on each unnamed body, and each body's compiled name.

    Bodies are listed in the order :func:`map_elements` visits them; the compiled
    name of a body in a ``<replicate>`` is that of its first copy.
    """
    names: list[str] = []

    def name(element: AnyElement, key: str | None, ancestors: Sequence[AnyElement]) -> AnyElement:
        if key != "body":
            return element
        own = get_attribute(element, "name")
        if own is None:
            own = f"{_MADE_UP}{len(names)}"
            while own in taken:
                own += "_"
            element = with_attributes(element, {"name": own})
        suffix = "".join(copy_suffix(a, 0) for a in reversed(ancestors) if a.tag == "replicate")
        names.append(str(own) + suffix)
        return element

    return map_elements(name, model), names


def _inertias(
    model: Mujoco, settings: Settings, taken: frozenset[str]
) -> tuple[Arrays, list[int], list[str]]:
    """Every body's compiled inertia under ``settings``, the id of each ``<body>``, body names."""
    import mujoco

    named, names = _named_bodies(model, taken)
    found = compiled(_variant(named, settings))
    ids = [mujoco.mj_name2id(found, mujoco.mjtObj.mjOBJ_BODY, name) for name in names]
    bodies = [
        mujoco.mj_id2name(found, mujoco.mjtObj.mjOBJ_BODY, i) or "" for i in range(found.nbody)
    ]
    return {field: getattr(found, field) for field in _INERTIA_FIELDS}, ids, bodies


def _with_inertials(model: Mujoco, values: Arrays, ids: list[int]) -> Mujoco:
    """``model`` with each ``<body>`` given the compiled inertia ``values`` at its id."""
    count = iter(ids)

    def write(element: AnyElement, key: str | None, ancestors: Sequence[AnyElement]) -> AnyElement:
        index = next(count) if key == "body" else -1
        if index < 0:
            return element
        inertial = Inertial(
            pos=values["body_ipos"][index],
            quat=values["body_iquat"][index],
            mass=float(values["body_mass"][index]),
            diaginertia=values["body_inertia"][index],
        )
        kept = [c for c in element.children if getattr(c, "tag", None) != "inertial"]
        return with_children(element, [inertial, *kept])

    return map_elements(write, model)


def inertia_kept(child: Mujoco, converted: Mujoco, mine: Settings, theirs: Settings) -> Mujoco:
    """``converted`` with the inertia MuJoCo gives each body of ``child`` written explicitly.

    Compiled with every body unfused and unaligned (the alignment a free joint asks
    for is made again from the same inertia), so that only inertia settings count.

    Examples:
        >>> from mjcf_model import loads
        >>> child = loads('<mujoco><worldbody><body><freejoint/><geom size="0.1" mass="2"/>'
        ...               '</body></worldbody></mujoco>')
        >>> settings = {"inertiafromgeom": "auto", "boundmass": "0", "boundinertia": "0",
        ...             "balanceinertia": "false", "inertiagrouprange": "0 5", "settotalmass": "-1"}
        >>> kept = inertia_kept(child, child, settings, {**settings, "settotalmass": "-1"})
        >>> kept.worldbody.bodies[0].elements[0].mass
        2.0

    """
    taken = declared_names(child).get("body", frozenset())
    settings = ", ".join(
        f"{n}={theirs[n]!r} (child: {mine[n]!r})" for n in INERTIA_SETTINGS if mine[n] != theirs[n]
    )
    try:
        wanted, ids, names = _inertias(child, mine, taken)
    except MjcfError as error:
        raise MjcfValueError(
            f"cannot keep the child's inertias under the parent's {settings}: MuJoCo does "
            f"not compile the child alone: {error}"
        ) from None
    result = _with_inertials(converted, wanted, ids)
    try:
        found = _inertias(result, theirs, taken)[0]
    except MjcfError as error:
        raise MjcfValueError(
            f"the child does not compile under the parent's {settings}, even with explicit "
            f"inertials; give the two models the same inertia settings ({error})"
        ) from None
    if len(found["body_mass"]) != len(names):  # not expected: the same tree is compiled
        raise MjcfValueError(f"the child compiles to other bodies under the parent's {settings}")
    for index, name in enumerate(names):
        if not all(
            np.allclose(wanted[f][index], found[f][index], rtol=1e-12, atol=0)
            for f in _INERTIA_FIELDS
        ):
            shown = "an unnamed body" if name.startswith(_MADE_UP) else f"body {name!r}"
            raise MjcfValueError(
                f"{shown} would get another mass or inertia under the parent's {settings}, "
                "even with an explicit <inertial>; give the two models the same inertia settings"
            )
    return result
