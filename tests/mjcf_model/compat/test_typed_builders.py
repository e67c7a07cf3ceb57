"""Builders: the same tags, attribute order and values as robosuite's ``new_*`` functions."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Callable
from typing import Any

import mujoco
import numpy as np
import pytest
from robosuite.utils import mjcf_utils

from mjcf_model import (
    Body,
    GenericElement,
    Geom,
    Inertial,
    Joint,
    MjcfLookupError,
    Motor,
    Position,
    Site,
    Texture,
    TypedElement,
    Velocity,
)
from mjcf_model.compat.mjcf_utils.constants import RED
from mjcf_model.compat.typed_builders import (
    new_actuator,
    new_body,
    new_element,
    new_geom,
    new_inertial,
    new_joint,
    new_site,
)
from mjcf_model.nodes.base import AnyElement, get_attribute
from mjcf_model.serializers import dumps, to_etree

Builder = Callable[..., Any]

#: (our builder, robosuite's builder, positional args, keyword args)
CASES: list[tuple[Builder, Builder, tuple[Any, ...], dict[str, Any]]] = [
    # The contract's section 6, item 2.
    (new_site, mjcf_utils.new_site, ("s",), {}),
    (new_site, mjcf_utils.new_site, (None,), {}),
    (new_geom, mjcf_utils.new_geom, ("g", "box", [0.1, 0.1, 0.1]), {}),
    (
        new_geom,
        mjcf_utils.new_geom,
        ("g", "sphere", [0.1]),
        {"group": None, "rgba": None, "material": "m"},
    ),
    (new_body, mjcf_utils.new_body, ("b",), {}),
    (new_joint, mjcf_utils.new_joint, ("j",), {"type": "free", "damping": "0.0005"}),
    (
        new_actuator,
        mjcf_utils.new_actuator,
        (),
        {"joint": "gz", "act_type": "position", "name": "a", "kp": "500"},
    ),
    (new_inertial, mjcf_utils.new_inertial, (), {"mass": 1.0, "diaginertia": [1, 1, 1]}),
    (
        new_element,
        mjcf_utils.new_element,
        ("body", None),
        {"pos": [0, 0, 1], "quat": None, "mass": 0.5, "flag": True},
    ),
    # More: defaults dropped, extra attributes first, numpy arrays, every actuator slot.
    (new_body, mjcf_utils.new_body, (None,), {"pos": None}),
    (new_body, mjcf_utils.new_body, ("b",), {"quat": [1, 0, 0, 0], "childclass": "arm"}),
    (
        new_site,
        mjcf_utils.new_site,
        ("tip",),
        {"type": "sphere", "group": 0, "rgba": None, "size": [0.002, 0.002, 0.002]},
    ),
    (new_site, mjcf_utils.new_site, ("s",), {"pos": np.array([0.5, 0, 1]), "rgba": [0, 1, 0, 1]}),
    (
        new_geom,
        mjcf_utils.new_geom,
        ("g0_vis", "box", np.array([0.02, 0.02, 0.02])),
        {"conaffinity": 0, "contype": 0, "mass": 1e-8, "rgba": [1, 0, 0, 1], "group": 1},
    ),
    (
        new_geom,
        mjcf_utils.new_geom,
        ("cyl", "cylinder", (0.03, 0.05)),
        {
            "margin": 0.001,
            "density": 1000.0,
            "friction": [1, 0.01, 0.001],
            "solref": [0.01, 0.5],
            "solimp": [0.9, 0.95, 0.001],
            "pos": None,
        },
    ),
    (new_joint, mjcf_utils.new_joint, (None,), {"type": "slide", "limited": True}),
    (
        new_joint,
        mjcf_utils.new_joint,
        ("hinge",),
        {"axis": np.array([0, 0, 1]), "range": [-1.57, 1.57], "damping": 0.1},
    ),
    (new_actuator, mjcf_utils.new_actuator, ("m", "j"), {"act_type": "motor", "gear": [100]}),
    (
        new_actuator,
        mjcf_utils.new_actuator,
        ("v", "j"),
        {"act_type": "velocity", "ctrlrange": [-1, 1], "ctrllimited": True, "kv": 10},
    ),
    (new_inertial, mjcf_utils.new_inertial, (), {"pos": None}),
    (new_inertial, mjcf_utils.new_inertial, ((0, 0, 0.1), 2), {"quat": [1, 0, 0, 0]}),
    (new_element, mjcf_utils.new_element, ("wheel", "w"), {"spokes": 5, "radius": [0.1]}),
    (
        new_element,
        mjcf_utils.new_element,
        ("texture", "t"),
        {"type": "cube", "builtin": "flat", "width": 100, "rgb1": [1, 1, 1]},
    ),
    (new_element, mjcf_utils.new_element, ("geom", "g"), {"castshadow": False, "size": [1]}),
]


def _numbers(text: str) -> list[float] | None:
    try:
        return [float(token) for token in text.split()]
    except ValueError:
        return None


def _assert_same(ours: AnyElement, theirs: ET.Element) -> None:
    mine = to_etree(ours)
    assert mine.tag == theirs.tag
    assert list(mine.attrib) == list(theirs.attrib)
    for key, text in theirs.attrib.items():
        expected = _numbers(text)
        if expected is None:
            assert mine.attrib[key] == text, key
        else:
            assert _numbers(mine.attrib[key]) == expected, key


def _case_id(case: tuple[Builder, Builder, tuple[Any, ...], dict[str, Any]]) -> str:
    builder, _, args, kwargs = case
    return f"{builder.__name__}{args!r}{sorted(kwargs)!r}"


@pytest.mark.parametrize("case", CASES, ids=[_case_id(c) for c in CASES])
def test_same_tag_attribute_order_and_values_as_robosuite(
    case: tuple[Builder, Builder, tuple[Any, ...], dict[str, Any]],
) -> None:
    """Tag, attribute names in order and values (numbers numerically) match robosuite."""
    ours, theirs, args, kwargs = case
    _assert_same(ours(*args, **kwargs), theirs(*args, **kwargs))


def _robosuite_text(element: ET.Element) -> str:
    """The text robosuite writes, with empty elements spelled `<a/>` as our writer does."""
    return ET.tostring(element, encoding="unicode").replace(" />", "/>") + "\n"


def test_text_equals_robosuites_where_its_numbers_are_shortest() -> None:
    """With int lists and text values robosuite writes exactly what we write."""
    assert dumps(new_site("s")) == _robosuite_text(mjcf_utils.new_site("s"))
    assert dumps(new_body(None, pos=None)) == _robosuite_text(mjcf_utils.new_body(None, pos=None))
    assert dumps(new_geom("g", "box", [0.1, 0.1, 0.1])) == _robosuite_text(
        mjcf_utils.new_geom("g", "box", [0.1, 0.1, 0.1])
    )
    kwargs = {"joint": "gz", "act_type": "position", "name": "a", "kp": "500"}
    assert dumps(new_actuator(**kwargs)) == _robosuite_text(mjcf_utils.new_actuator(**kwargs))


def test_results_are_typed_nodes_of_the_right_class() -> None:
    """Each builder returns its typed class; unknown tags give a generic element."""
    assert type(new_body("b")) is Body
    assert type(new_geom("g", "box", [1, 1, 1])) is Geom
    assert type(new_joint("j")) is Joint
    assert type(new_site("s")) is Site
    assert type(new_inertial()) is Inertial
    assert type(new_actuator("m", "j")) is Motor
    assert type(new_actuator("p", "j", act_type="position", kp=5)) is Position
    assert type(new_actuator("v", "j", "velocity")) is Velocity
    assert type(new_element("texture", "t")) is Texture
    assert type(new_element("joint", "j")) is Joint
    assert type(new_element("motor", "m")) is Motor
    assert isinstance(new_element("wheel"), GenericElement)
    assert new_geom("g", "box", [1, 2, 3]).size == (1.0, 2.0, 3.0)
    assert new_actuator("p", "j", act_type="position", kp="500").kp == 500.0


def test_numpy_arrays_and_scalars_are_accepted() -> None:
    """Arrays of any dtype and numpy scalars become plain typed values."""
    geom = new_geom(
        "g",
        "box",
        np.array([0.1, 0.2, 0.3]),
        pos=np.zeros(3, dtype=np.float32),
        group=np.int64(1),
        rgba=np.array([1, 0, 0, 1]),
    )
    assert geom.size == (0.1, 0.2, 0.3)
    assert geom.pos == (0.0, 0.0, 0.0)
    assert geom.group == 1 and type(geom.group) is int
    assert geom.rgba == (1.0, 0.0, 0.0, 1.0)
    body = new_element("body", "b", pos=np.array([1, 2, 3]), weight=np.float64(0.5))
    assert isinstance(body, Body) and body.pos == (1.0, 2.0, 3.0)
    assert get_attribute(body, "weight") == "0.5"


def test_unknown_attributes_go_to_extra_and_dclass_is_class() -> None:
    """Attributes a class does not model are kept as text; ``dclass`` writes ``class``."""
    geom = new_geom("g", "box", [1, 1, 1], dclass="visual", glow=2)
    assert geom.dclass == "visual"
    assert geom.extra == {"glow": "2"}
    assert list(to_etree(geom).attrib) == ["class", "glow", "type", "size", "pos", "group", "name"]
    _assert_same(geom, mjcf_utils.new_geom("g", "box", [1, 1, 1], **{"class": "visual", "glow": 2}))
    inertial = new_inertial(mass=1, name="i")
    assert inertial.extra == {"name": "i"}


def test_default_actuator_type_is_motor_not_robosuites_section_tag() -> None:
    """The default act_type is ``motor``; robosuite's is the section tag ``actuator``."""
    assert mjcf_utils.new_actuator("a", "j").tag == "actuator"
    ours = new_actuator("a", "j")
    assert ours.tag == "motor"
    _assert_same(ours, mjcf_utils.new_actuator("a", "j", act_type="motor"))


def test_unknown_actuator_type_raises_a_lookup_error() -> None:
    """An ``act_type`` that is no actuator element names the ones that are."""
    with pytest.raises(MjcfLookupError, match=r"'actuator'.*general, intvelocity, motor"):
        new_actuator("a", "j", act_type="actuator")
    with pytest.raises(KeyError):
        new_actuator("a", "j", act_type="geom")


def test_red_is_robosuites_red() -> None:
    """``RED`` equals robosuite's ``RED`` and is the site default."""
    assert RED == mjcf_utils.RED
    assert new_site("s").rgba == tuple(RED)


def test_inputs_are_not_mutated() -> None:
    """Lists and dicts passed in are left as they were."""
    size = [0.1, 0.2, 0.3]
    extra: dict[str, Any] = {"rgba": [1, 0, 0, 1]}
    geom = new_geom("g", "box", size, **extra)
    assert size == [0.1, 0.2, 0.3] and extra == {"rgba": [1, 0, 0, 1]}
    size[0] = 9.0
    assert geom.size == (0.1, 0.2, 0.3)


def _ours_model() -> str:
    body = new_body("b", pos=[0, 0, 1])
    children = [
        new_joint("hinge", type="hinge", axis=[0, 1, 0], range=[-1, 1], damping=0.5),
        new_geom("g", "box", [0.1, 0.2, 0.3], pos=[0, 0, 0.1], rgba=[0, 1, 0, 1]),
        new_geom("v", "sphere", [0.05], group=1, contype=0, conaffinity=0),
        new_site("s", pos=[0.1, 0, 0]),
        new_inertial(mass=2.0, diaginertia=[0.1, 0.1, 0.1]),
    ]
    body = Body(name=body.name, pos=body.pos, children=children)
    actuator = new_actuator("a", "hinge", act_type="position", kp=50, ctrlrange=[-1, 1])
    return (
        f"<mujoco><worldbody>{dumps(body)}</worldbody>"
        f"<actuator>{dumps(actuator)}</actuator></mujoco>"
    )


def _robosuite_model() -> str:
    body = mjcf_utils.new_body("b", pos=[0, 0, 1])
    body.append(
        mjcf_utils.new_joint("hinge", type="hinge", axis=[0, 1, 0], range=[-1, 1], damping=0.5)
    )
    body.append(
        mjcf_utils.new_geom("g", "box", [0.1, 0.2, 0.3], pos=[0, 0, 0.1], rgba=[0, 1, 0, 1])
    )
    body.append(mjcf_utils.new_geom("v", "sphere", [0.05], group=1, contype=0, conaffinity=0))
    body.append(mjcf_utils.new_site("s", pos=[0.1, 0, 0]))
    body.append(mjcf_utils.new_inertial(mass=2.0, diaginertia=[0.1, 0.1, 0.1]))
    actuator = mjcf_utils.new_actuator("a", "hinge", act_type="position", kp=50, ctrlrange=[-1, 1])
    return (
        f"<mujoco><worldbody>{ET.tostring(body, encoding='unicode')}</worldbody>"
        f"<actuator>{ET.tostring(actuator, encoding='unicode')}</actuator></mujoco>"
    )


def test_built_model_compiles_like_robosuites() -> None:
    """MuJoCo compiles both models to the same numbers."""
    ours = mujoco.MjModel.from_xml_string(_ours_model())
    theirs = mujoco.MjModel.from_xml_string(_robosuite_model())
    for field in (
        "body_pos",
        "body_mass",
        "body_inertia",
        "jnt_range",
        "dof_damping",
        "geom_size",
        "geom_pos",
        "geom_rgba",
        "geom_group",
        "geom_contype",
        "site_pos",
        "site_size",
        "site_rgba",
        "actuator_gainprm",
        "actuator_biasprm",
        "actuator_ctrlrange",
    ):
        assert np.array_equal(getattr(ours, field), getattr(theirs, field)), field


def test_typed_element_attribute_order_is_recorded() -> None:
    """The order is kept in ``attribute_order`` (ignored by ``==``)."""
    site = new_site("s", type="sphere")
    assert isinstance(site, TypedElement)
    assert site.attribute_order == ("type", "pos", "size", "rgba", "name")
    assert site == Site(name="s", type="sphere", pos=(0, 0, 0), size=(0.005,), rgba=tuple(RED))
