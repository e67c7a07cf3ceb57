"""Tests of ``mjcf_model.serializers.etree``: ElementTree elements and nodes, both ways."""

from __future__ import annotations

import xml.etree.ElementTree as ET

import mujoco
import pytest

from mjcf_model import (
    Comment,
    GenericElement,
    Geom,
    MjcfValueError,
)
from mjcf_model.bridge.compare import model_differences
from mjcf_model.serializers import dumps, from_etree, to_etree
from mjcf_model.serializers.etree import converted_children

#: A model with a comment, a light, and a body holding a joint and a geom.
MODEL = """<mujoco model="m">
  <!-- lights -->
  <worldbody>
    <light pos="0 0 3"/>
    <body name="b" pos="0 0 1"><joint/><geom size="0.1" group="1"/></body>
  </worldbody>
</mujoco>
"""


def test_an_element_tree_converts_to_the_model_mujoco_compiles_and_back() -> None:
    """Nodes from the tree write a model MuJoCo compiles as the tree; ``to_etree`` mirrors."""
    tree = ET.fromstring(MODEL)
    model = from_etree(tree)
    expected = mujoco.MjModel.from_xml_string(MODEL)
    assert model_differences(expected, mujoco.MjModel.from_xml_string(dumps(model))) == []
    back = to_etree(model)
    assert [c.tag for c in back] == [c.tag for c in tree]
    assert from_etree(back) == model


def test_only_elements_and_comments_become_nodes() -> None:
    """Processing instructions are left out; comments are kept in place."""
    parser = ET.XMLParser(target=ET.TreeBuilder(insert_comments=True, insert_pis=True))
    body = ET.fromstring("<body><!-- a --><geom size='1'/><?pi x?><site/></body>", parser)
    kept = converted_children(body)
    assert len(body) == 4 and len(kept) == 3
    node = from_etree(body)
    assert [type(c).__name__ for c in node.children] == ["Comment", "Geom", "Site"]
    assert node.children[0] == Comment(text=" a ")


def test_untyped_conversion_keeps_text_as_given() -> None:
    """With ``typed=False`` attributes stay text; the context decides a tag's class."""
    geom = ET.fromstring('<geom group="1.0" size=".1"/>')
    untyped = from_etree(geom, typed=False)
    assert isinstance(untyped, GenericElement) and untyped.attributes["group"] == "1.0"
    assert isinstance(from_etree(ET.fromstring('<geom size=".1"/>')), Geom)
    joint = from_etree(ET.fromstring('<joint joint1="a"/>'), context="equality")
    assert type(joint).__name__ == "EqualityJoint"


def test_from_etree_error_names_the_element_path() -> None:
    """Errors from ElementTree input name the path, with the index among same-tag siblings."""
    import xml.etree.ElementTree as ET

    from mjcf_model.serializers import from_etree

    tree = ET.fromstring(
        "<mujoco><worldbody><geom size='1'/><body name='b'><geom size='1'/>"
        "<geom pos='0 1'/></body></worldbody></mujoco>"
    )
    pos = from_etree(tree).worldbody.bodies[0].geoms[1].pos  # type: ignore[attr-defined]
    with pytest.raises(MjcfValueError) as caught:
        pos[0]
    assert caught.value.path == "/mujoco/worldbody/body[@name='b']/geom[2]"
    assert "attribute 'pos': expected 3 numbers, found 2" in str(caught.value)
