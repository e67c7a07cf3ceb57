"""Tests of ``mjcf_model.compat.geom_roles``, with robosuite 1.5.2 as the referee."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from typing import Any

import pytest
from robosuite.utils import mjcf_utils

from mjcf_model import Body, Geom, Site
from mjcf_model.compat import categorized
from mjcf_model.compat.geom_roles import (
    geom_role,
    role_of_group,
    with_collision_color,
    with_visual_material,
)
from mjcf_model.nodes.base import get_attribute
from mjcf_model.serializers import from_etree, loads, to_etree

#: robosuite's category of each role (its ``sort_elements`` filter).
CATEGORY = {"collision": "contact_geoms", "visual": "visual_geoms", None: None}

#: Geoms in every group spelling robosuite tells apart, with and without materials.
BODY = from_etree(
    ET.fromstring(
        """<body name="b">
      <geom name="none" size="0.1" material="wood"/>
      <geom name="zero" size="0.1" group="0"/>
      <geom name="one" size="0.1" group="1"/>
      <geom name="one_with_material" size="0.1" group="1" material="metal"/>
      <geom name="two" size="0.1" group="2"/>
      <geom name="one_point_zero" size="0.1" group="1.0"/>
      <body name="inner">
        <geom name="skip" size="0.1"/><geom name="deep" size="0.1" group="1"/>
      </body>
      <site name="s"/>
    </body>"""
    )
)


@pytest.mark.parametrize("group", [None, "0", "1", "2", "1.0"])
def test_a_geoms_role_is_robosuites_category(group: str | None) -> None:
    """Group unwritten or ``0``: collision; ``1``: visual; other text (``1.0``): no role."""
    written = "" if group is None else f' group="{group}"'
    element = ET.fromstring(f'<geom size="0.1"{written}/>')
    category = mjcf_utils._element_filter(element, None)
    geom = from_etree(element)
    assert isinstance(geom, Geom)
    assert CATEGORY[geom_role(geom)] == category
    assert CATEGORY[role_of_group(group)] == category


@pytest.mark.parametrize("group", ["01", "00", "+1", " 1", "1", "0"])
def test_a_loaded_geom_has_the_role_of_its_groups_spelling(group: str) -> None:
    """Read from text, ``group="01"`` is 1 but written ``01``: robosuite gives it no role."""
    text = f'<mujoco><worldbody><geom name="g" size="0.1" group="{group}"/></worldbody></mujoco>'
    category = mjcf_utils._element_filter(ET.fromstring(text)[0][0], None)
    model = loads(text)
    (geom,) = model.worldbody.geoms
    assert isinstance(geom, Geom) and geom.group == int(group)
    assert CATEGORY[geom_role(geom)] == category
    found = categorized(model)
    assert [g.name for g in found.contact_geoms + found.visual_geoms] == (
        [] if category is None else ["g"]
    )


def test_only_geoms_have_a_role() -> None:
    """A site or a body has no geom role, whatever its ``group``."""
    assert geom_role(Site(group=1)) is None
    assert geom_role(Body()) is None


def test_collision_color_is_robosuites_recolor_collision_geoms() -> None:
    """Every collision geom not excluded gets the colour and loses its material, at any depth."""
    calls: list[int] = []

    def color() -> Any:
        calls.append(1)
        return (0.5, 0.25, 0.0, 1.0)

    def excluded(element: Any) -> bool:
        return element.get("name") == "skip"

    theirs = to_etree(BODY)
    mjcf_utils.recolor_collision_geoms(theirs, [0.5, 0.25, 0.0, 1.0], exclude=excluded)
    ours = with_collision_color(BODY, color, exclude=lambda e: get_attribute(e, "name") == "skip")
    assert ours == from_etree(theirs)
    assert calls == [1]
    assert with_collision_color(Body(children=[Site()]), color) == Body(children=[Site()])
    assert calls == [1]  # no collision geom: the colour is never made


def test_visual_material_is_robosuites_add_material_rule() -> None:
    """Visual geoms without a material get it, at any depth; ``used`` is robosuite's flag."""
    theirs = to_etree(BODY)
    _, material, _, used = mjcf_utils.add_material(theirs)
    ours, ours_used = with_visual_material(BODY, material.get("name"))
    assert ours == from_etree(theirs)
    assert ours_used is used is True
    collision_only = Body(children=[Geom(size=(0.1,))])
    _, _, _, used = mjcf_utils.add_material(to_etree(collision_only))
    assert with_visual_material(collision_only, "default_mat") == (collision_only, used)


def test_unchanged_subtrees_are_the_inputs_own() -> None:
    """A subtree without a geom to change is returned as it was, not rebuilt."""
    recolored = with_collision_color(BODY, lambda: (1.0, 0.0, 0.0, 1.0))
    assert recolored.children[-1] is BODY.children[-1]  # the site
    painted, _ = with_visual_material(BODY, "m")
    assert painted.children[0] is BODY.children[0]  # a collision geom
