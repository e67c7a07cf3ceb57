"""The scaling cases of joints, geoms, sites, cameras, lights and pairs, and what cases are.

Each :class:`ScaleCase` sets one attribute of one schema key on the base model of
:mod:`tests.support.schema_cases`, and says where MuJoCo's compiled model holds its value:
scaling by 2 must multiply that value by ``2 ** power`` (1 for a length, 2 for an area).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import attrs
import mujoco
import numpy as np

from tests.support.schema_model import model


@attrs.frozen
class ScaleCase:
    """A model whose ``key`` element sets the length ``attribute``."""

    key: str
    attribute: str
    xml: str
    #: The compiled value the attribute sets.
    value: Callable[[Any], Any]
    #: The power of the factor that value scales by.
    power: int = 1
    #: How closely the compiled value follows the factor.
    rtol: float = 1e-9


def of(field: str, kind: str, name: str, columns: slice = slice(None)) -> Callable[[Any], Any]:
    """The row of ``field`` that belongs to the ``kind`` object ``name`` (some of its columns)."""

    def value(compiled: Any) -> Any:
        index = mujoco.mj_name2id(compiled, getattr(mujoco.mjtObj, f"mjOBJ_{kind.upper()}"), name)
        assert index >= 0, f"no {kind} {name!r}"
        return np.atleast_1d(np.asarray(getattr(compiled, field))[index])[columns]

    return value


def of_joint_qpos(field: str, name: str) -> Callable[[Any], Any]:
    """The ``qpos``-sized ``field`` entry of the one-coordinate joint ``name``."""

    def value(compiled: Any) -> Any:
        index = mujoco.mj_name2id(compiled, mujoco.mjtObj.mjOBJ_JOINT, name)
        return np.asarray(getattr(compiled, field))[compiled.jnt_qposadr[index]]

    return value


def setting(group: str, field: str) -> Callable[[Any], Any]:
    """A global value: ``compiled.<group>.<field>`` (``opt``, ``stat``)."""
    return lambda compiled: np.asarray(getattr(getattr(compiled, group), field))


def whole(field: str) -> Callable[[Any], Any]:
    """Every value of ``field``."""
    return lambda compiled: np.asarray(getattr(compiled, field))


SLIDER = '<body name="carriage" pos="0 2 0"><joint name="rail" {}/><geom size="0.1"/></body>'
_JOINT_SETTINGS = {
    "pos": ('pos="0 0 0.1"', of("jnt_pos", "joint", "rail")),
    "range": ('range="-0.5 0.5"', of("jnt_range", "joint", "rail")),
    "ref": ('ref="0.1"', of_joint_qpos("qpos0", "rail")),
    "springref": ('springref="0.2"', of_joint_qpos("qpos_spring", "rail")),
    "margin": ('margin="0.01"', of("jnt_margin", "joint", "rail")),
}


def _joint_cases() -> list[ScaleCase]:
    cases = []
    for attribute, (text, value) in _JOINT_SETTINGS.items():
        own = model(world=SLIDER.format(f'type="slide" axis="1 0 0" {text}'))
        classed = model(
            default=f'<default class="rails"><joint type="slide" axis="1 0 0" {text}/></default>',
            world=SLIDER.format('class="rails"'),
        )
        cases += [
            ScaleCase("body/joint", attribute, own, value),
            ScaleCase("default/joint", attribute, classed, value),
        ]
    return cases


#: The attributes of a geom or site, each with the value it compiles to.
_GEOM_SETTINGS = {
    "pos": ('pos="0.1 0.2 0.3" size="0.1"', "pos", slice(None)),
    "fromto": ('type="capsule" fromto="0 0 0 0 0 0.4" size="0.05"', "size", slice(None)),
    "size": ('type="box" size="0.1 0.2 0.3"', "size", slice(None)),
    "margin": ('size="0.1" margin="0.01"', "margin", slice(None)),
    "gap": ('size="0.1" gap="0.01"', "gap", slice(None)),
    "friction": ('size="0.1" friction="1 0.01 0.001"', "friction", slice(1, None)),
}


def _element_cases(tag: str, kind: str, attributes: tuple[str, ...]) -> list[ScaleCase]:
    prefix = "cam" if kind == "camera" else kind
    cases = []
    for attribute in attributes:
        text, field, columns = _GEOM_SETTINGS[attribute]
        cases += _own_and_classed(
            tag, attribute, text, of(f"{prefix}_{field}", kind, "probe", columns)
        )
    return cases


def _own_and_classed(
    tag: str, attribute: str, text: str, value: Callable[[Any], Any]
) -> list[ScaleCase]:
    """The element ``probe`` writing ``text`` itself, and taking it from a class."""
    own = model(world=f'<{tag} name="probe" {text}/>')
    classed = model(
        default=f'<default class="probes"><{tag} {text}/></default>',
        world=f'<{tag} name="probe" class="probes"/>',
    )
    return [
        ScaleCase(f"body/{tag}", attribute, own, value),
        ScaleCase(f"default/{tag}", attribute, classed, value),
    ]


_GEOMS = _element_cases("geom", "geom", tuple(_GEOM_SETTINGS))
_SITES = _element_cases("site", "site", ("pos", "fromto", "size"))
_LENS = 'resolution="8 8" sensorsize="0.02 0.02" focal="0.01 0.01" principal="0.001 0.001"'
_CAMERA_SETTINGS = {
    "pos": ('pos="0.1 0.2 0.3"', of("cam_pos", "camera", "probe")),
    "ipd": ('ipd="0.07"', of("cam_ipd", "camera", "probe")),
    "sensorsize": (_LENS, of("cam_sensorsize", "camera", "probe")),
    "focal": (_LENS, of("cam_intrinsic", "camera", "probe", slice(0, 2))),
    "principal": (_LENS, of("cam_intrinsic", "camera", "probe", slice(2, 4))),
}
_LIGHT_SETTINGS = {
    "pos": ('pos="0.1 0.2 0.3"', of("light_pos", "light", "probe")),
    "bulbradius": ('bulbradius="0.05"', of("light_bulbradius", "light", "probe")),
    "range": ('range="5"', of("light_range", "light", "probe")),
}


def _lens_cases() -> list[ScaleCase]:
    cases = []
    for tag, settings in (("camera", _CAMERA_SETTINGS), ("light", _LIGHT_SETTINGS)):
        for attribute, (text, value) in settings.items():
            cases += _own_and_classed(tag, attribute, text, value)
    return cases


_PAIR_SETTINGS = {
    "margin": ('margin="0.01"', "pair_margin", slice(None)),
    "gap": ('gap="0.01"', "pair_gap", slice(None)),
    "friction": ('friction="1 1 0.01 0.001 0.001"', "pair_friction", slice(2, None)),
}


def _pair_cases() -> list[ScaleCase]:
    cases = []
    for attribute, (text, field, columns) in _PAIR_SETTINGS.items():
        value = lambda compiled, f=field, c=columns: np.atleast_1d(getattr(compiled, f)[0])[c]  # noqa: E731
        own = model(contact=f'<pair geom1="upper" geom2="knob" {text}/>')
        classed = model(
            default=f'<default class="pairs"><pair {text}/></default>',
            contact='<pair class="pairs" geom1="upper" geom2="knob"/>',
        )
        cases += [
            ScaleCase("contact/pair", attribute, own, value),
            ScaleCase("default/pair", attribute, classed, value),
        ]
    return cases


def element_cases() -> list[ScaleCase]:
    """The cases of joints, geoms, sites, cameras, lights and contact pairs."""
    return [*_joint_cases(), *_GEOMS, *_SITES, *_lens_cases(), *_pair_cases()]
