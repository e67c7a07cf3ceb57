"""Tests of ``mjcf_model.compat.mjcf_utils.scaling``."""

from __future__ import annotations

import warnings
import xml.etree.ElementTree as ET
from typing import Any

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from mjcf_model.nodes import Body, Geom, Joint, Mesh, Site
from mjcf_model.serializers import to_etree
from mjcf_model.strategies import elements
from tests.support.compat_utils import (
    differential,
    messy_trees,
    ours,
    rs,
    scale_each,
    scale_model,
    tree_bytes,
)

# -- compat ``mjcf_utils`` tree functions against robosuite's, on generated models and the
#    corpus.
#
# Every case runs robosuite's function and ours on copies of one tree and
# requires the same bytes from ``ET.tostring``, the same return value (elements
# compared by position) and the same exception type. Where robosuite crashes on
# valid MJCF (numbers separated by several spaces; unnamed elements and
# ``return_first`` in ``find_elements_by_substring``), ours must give what
# robosuite gives on the input it can read.


scales = (
    st.integers(1, 4)
    | st.floats(0.1, 10)
    | st.lists(st.floats(0.1, 10), min_size=3, max_size=3)
    | st.lists(st.integers(1, 3), min_size=3, max_size=3).map(np.array)
)


def _quiet(operation: Any) -> Any:
    """The operation with numpy's overflow warnings silenced (extreme generated numbers)."""

    def quiet(module: Any, root: ET.Element) -> Any:
        with warnings.catch_warnings(), np.errstate(all="ignore"):
            warnings.simplefilter("ignore")
            return operation(module, root)

    return quiet


# -- generated trees ------------------------------------------------------------------------


#: The tags robosuite's scale_* functions read.
SCALED_TAGS = ("geom", "site", "body", "mesh", "joint")


@given(messy_trees(aim=SCALED_TAGS), scales, st.booleans(), st.booleans())
def test_scaling_matches_robosuite_on_generated_trees(
    tree: tuple[ET.Element, tuple[int, ...]], scale: Any, sites: bool, slide: bool
) -> None:
    """scale_mjcf_model and each scale_*_element give robosuite's bytes."""
    root, _path = tree
    differential("scale_mjcf_model", root, scale_model(scale, sites, slide), right_on_crash=True)
    for function, tag in [
        ("scale_geom_element", "geom"),
        ("scale_site_element", "site"),
        ("scale_body_element", "body"),
        ("scale_mesh_element", "mesh"),
    ]:
        differential(function, root, scale_each(function, tag, scale), right_on_crash=True)
    differential(
        "scale_joint_element",
        root,
        scale_each("scale_joint_element", "joint", scale, slide),
        right_on_crash=True,
    )


ELEMENT_SCALERS = {
    Geom: "scale_geom_element",
    Site: "scale_site_element",
    Body: "scale_body_element",
    Mesh: "scale_mesh_element",
    Joint: "scale_joint_element",
}


@given(
    st.sampled_from(sorted(ELEMENT_SCALERS, key=lambda c: c.__name__)).flatmap(elements),
    scales,
    st.booleans(),
)
def test_element_scaling_matches_robosuite_on_generated_elements(
    node: Any, scale: Any, slide: bool
) -> None:
    """Each scale_*_element gives robosuite's bytes (or error) on arbitrary attribute values."""
    function = ELEMENT_SCALERS[type(node)]
    extra = (slide,) if function == "scale_joint_element" else ()
    element = to_etree(node)
    differential(function, element, _quiet(scale_each(function, element.tag, scale, *extra)))


# -- robosuite's ``scale_*_element`` functions at their edges, robosuite 1.5.2 the referee. ----
#
# The generated and corpus trees (``tests/support/compat_utils.py``) never hold a slide
# joint with a zero axis or a size of four numbers, and compare only the type of an
# error: these cases compare the trees and the whole message.


SCALE_FUNCTIONS = ["geom", "site", "body", "mesh", "joint"]


@pytest.mark.parametrize("axis", ["0 0 0", "0 0 0.0", "0 3 4"])
@pytest.mark.parametrize("slide", [True, False])
def test_a_slide_joint_range_scales_by_its_axis_as_robosuite_scales_it(
    axis: str, slide: bool
) -> None:
    """A zero axis scales the range by the x factor; any other by the scaled unit axis."""
    root = ET.fromstring(
        f'<body><joint type="slide" axis="{axis}" range="-1 2" pos="1 1 1"/></body>'
    )
    differential(
        "scale_joint_element (axis)",
        root,
        lambda module, tree: module.scale_joint_element(tree[0], np.array([2, 3, 5]), slide),
    )


def test_a_zero_axis_range_is_the_x_factor_times_the_range() -> None:
    """The value robosuite writes, stated: x is 2, so ``-1 2`` becomes ``-2 4``."""
    joint = ET.fromstring('<joint type="slide" axis="0 0 0" range="-1 2"/>')
    ours.scale_joint_element(joint, np.array([2.0, 3.0, 5.0]))
    assert joint.get("range") == "-2.0 4.0"


@pytest.mark.parametrize("tag", ["geom", "site"])
@pytest.mark.parametrize("size", ["1 2 3 4", "1 2 3 4 5"])
def test_a_size_of_more_than_three_numbers_raises_robosuites_message(tag: str, size: str) -> None:
    """The same ``ValueError`` text as robosuite, naming the geom or the site."""
    theirs = ET.fromstring(f'<{tag} size="{size}"/>')
    mine = ET.fromstring(f'<{tag} size="{size}"/>')
    scale = np.array([1.0, 2.0, 3.0])
    with pytest.raises(ValueError) as expected:
        getattr(rs, f"scale_{tag}_element")(theirs, scale)
    assert str(expected.value) == f"Unsupported {tag} size dimensions."
    with pytest.raises(ValueError, match=f"^Unsupported {tag} size dimensions\\.$"):
        getattr(ours, f"scale_{tag}_element")(mine, scale)
    assert tree_bytes(mine) == tree_bytes(theirs)


@pytest.mark.parametrize("tag", SCALE_FUNCTIONS)
def test_each_scale_element_function_carries_robosuites_name(tag: str) -> None:
    """``__name__`` and ``__qualname__`` are robosuite's (tracebacks, ``functools.wraps``)."""
    name = f"scale_{tag}_element"
    mine, theirs = getattr(ours, name), getattr(rs, name)
    assert (
        (mine.__name__, mine.__qualname__)
        == (theirs.__name__, theirs.__qualname__)
        == (
            name,
            name,
        )
    )
    assert mine.__doc__ is not None
    assert mine.__doc__.startswith("Scale ")
    assert f"scaled_{tag}" in mine.__doc__


@pytest.mark.parametrize("tag", ["geom", "site", "body", "mesh"])
def test_each_scale_element_function_scales_the_element_it_is_given(tag: str) -> None:
    """Each writes robosuite's bytes onto the element passed, keeping a foreign attribute."""
    text = f'<{tag} pos="1 2 3" size="0.1 0.2" scale="1 2 1" extra="kept"/>'
    theirs, mine = ET.fromstring(text), ET.fromstring(text)
    scale = np.array([2.0, 3.0, 4.0])
    getattr(rs, f"scale_{tag}_element")(theirs, scale)
    getattr(ours, f"scale_{tag}_element")(mine, scale)
    assert tree_bytes(mine) == tree_bytes(theirs)
    assert tree_bytes(mine) != tree_bytes(ET.fromstring(text))


def test_a_slide_joint_without_an_axis_scales_by_robosuites_default_x_axis() -> None:
    """Robosuite takes a missing axis as ``1 0 0`` (not MuJoCo's ``0 0 1``): the x factor."""
    root = ET.fromstring('<body><joint type="slide" range="-1 2"/></body>')
    differential(
        "scale_joint_element (no axis)",
        root,
        lambda module, tree: module.scale_joint_element(tree[0], np.array([2, 3, 5])),
    )
    joint = ET.fromstring('<joint type="slide" range="-1 2"/>')
    ours.scale_joint_element(joint, np.array([2.0, 3.0, 5.0]))
    assert joint.get("range") == "-2.0 4.0"


def test_scaling_a_model_scales_slide_ranges_unless_told_not_to() -> None:
    """``scale_mjcf_model``'s and ``scaled_joint``'s default is robosuite's: ranges scale."""
    from mjcf_model.compat.mjcf_utils.scaling import scaled_joint
    from mjcf_model.nodes.base import GenericElement

    text = '<body><body><joint type="slide" axis="0 0 1" range="-1 2"/></body></body>'
    differential(
        "scale_mjcf_model (default)",
        ET.fromstring(text),
        lambda module, tree: module.scale_mjcf_model(
            tree, ET.Element("asset"), [1, 1, 3], module.get_elements
        ),
    )
    obj = ET.fromstring(text)
    ours.scale_mjcf_model(obj, ET.Element("asset"), [1, 1, 3], ours.get_elements)
    assert obj[0][0].get("range") == "-3.0 6.0"
    joint = GenericElement(tag="joint", attributes={"type": "slide", "range": "-1 2"})
    assert scaled_joint(joint, np.array([2.0, 1.0, 1.0])).attributes["range"] == "-2.0 4.0"
