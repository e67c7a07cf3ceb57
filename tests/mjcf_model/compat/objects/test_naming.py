"""Tests of ``mjcf_model.compat.objects.naming``."""

from __future__ import annotations

import uuid
import xml.etree.ElementTree as ET
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import pytest
import robosuite.models.objects as rs
from robosuite.utils import mjcf_utils as rs_utils

from mjcf_model.compat import objects as ours
from mjcf_model.compat.objects import naming
from mjcf_model.compat.objects.naming import naming_skeleton, robosuite_prefixed
from mjcf_model.serializers import from_etree, to_etree
from tests.support.compat_objects import _OBJECT, assert_same_object
from tests.support.plan_counting import PLANNED_AT_THE_SECOND_COPY

# -- Objects made again and again (files read once, names planned once) against robosuite. -----


def test_primitives_of_other_sizes_and_names_match_robosuite() -> None:
    """Boxes of one shape but new sizes and names, made in turn, are robosuite's boxes."""
    sizes = np.random.default_rng(3).uniform(0.01, 0.05, size=(6, 3))
    for index, size in enumerate(sizes):
        name = f"box{index % 3}"
        assert_same_object(ours.BoxObject(name, size=size), rs.BoxObject(name, size=size))


def test_composites_made_again_match_robosuite() -> None:
    """A composite made twice, with one name and then another, is robosuite's both times."""
    spec = {
        "total_size": [0.1, 0.1, 0.05],
        "geom_types": ["box", "box"],
        "geom_sizes": [[0.1, 0.1, 0.01], [0.01, 0.1, 0.05]],
        "geom_locations": [[0, 0, 0], [0, 0, 0.02]],
    }
    for name in ("shelf", "shelf", "rack"):
        assert_same_object(ours.CompositeObject(name, **spec), rs.CompositeObject(name, **spec))


def test_cans_made_again_are_independent_and_match_robosuite() -> None:
    """Cans made in turn are robosuite's; changing one's elements leaves the next one alone."""
    first = ours.CanObject("can")
    first.get_obj().set("pos", "1 2 3")
    for name in ("can", "other"):
        assert_same_object(ours.CanObject(name), rs.CanObject(name))


def test_joints_given_by_arrays_match_robosuite(tmp_path: Path) -> None:
    """Joint attributes given as arrays (nothing to remember them by) are robosuite's."""
    path = tmp_path / "thing.xml"
    path.write_text(_OBJECT.format(scale="1 1 1"))
    for axis in ([0, 0, 1], [0, 1, 0]):
        joints = [{"type": "hinge", "axis": np.array(axis)}]
        theirs_joints = [{"type": "hinge", "axis": np.array(axis)}]
        mine = ours.MujocoXMLObject(str(path), name="t", joints=joints)
        theirs = rs.MujocoXMLObject(str(path), name="t", joints=theirs_joints)
        assert_same_object(mine, theirs)
        assert mine.get_obj().find("joint").get("axis") == " ".join(str(v) for v in axis)


def test_joint_values_equal_as_numbers_but_written_apart_match_robosuite(tmp_path: Path) -> None:
    """``True``, ``1`` and ``1.0`` are equal keys yet robosuite writes them apart; so do these."""
    path = tmp_path / "thing.xml"
    path.write_text(_OBJECT.format(scale="1 1 1"))
    for limited in (True, 1, 1.0):
        joints = [{"type": "hinge", "limited": limited, "range": "-1 1"}]
        mine = ours.MujocoXMLObject(str(path), name="t", joints=[dict(joints[0])])
        theirs = rs.MujocoXMLObject(str(path), name="t", joints=[dict(joints[0])])
        assert_same_object(mine, theirs)
        assert mine.get_obj().find("joint").get("limited") == theirs.get_obj().find("joint").get(
            "limited"
        )


# -- Objects' names are prefixed once per shape, then by a plan: robosuite 1.5.2 the referee. --
#
# ``robosuite_prefixed`` prefixes the first tree of a naming skeleton directly, traces a
# plan on the second, and applies that plan from then on. Every result must be the
# bytes robosuite's ``add_prefix`` writes, whatever the exclusions of the call; and the
# plan must be traced once per skeleton, not once per tree (the speed it is for).


def object_tree(tag: str, size: str) -> Any:
    """A body with a named geom, site and joint, and a geom using a material, all unique to ``tag``.

    Trees of one ``tag`` share a naming skeleton; ``size`` is not part of it.
    """
    text = (
        f'<body name="{tag}_main"><joint name="{tag}_hinge"/>'
        f'<geom name="{tag}_g0" size="{size}" material="{tag}_mat"/>'
        f'<site name="{tag}_s0" size="{size}"/>'
        f'<body name="{tag}_inner"><geom size="{size}"/></body></body>'
    )
    return from_etree(ET.fromstring(text))


def robosuite_bytes(tree: Any, prefix: str, exclude: Callable[[str], bool] | None) -> bytes:
    """What robosuite's ``add_prefix`` makes of ``tree``."""
    element = to_etree(tree)
    rs_utils.add_prefix(element, prefix, exclude=exclude)
    return ET.tostring(element)


def our_bytes(tree: Any, prefix: str, exclude: Callable[[str], bool] | None) -> bytes:
    """What ``robosuite_prefixed`` makes of ``tree``."""
    return ET.tostring(to_etree(robosuite_prefixed(tree, prefix, exclude)))


def test_a_plan_is_traced_at_the_second_tree_of_a_skeleton_and_used_after(
    plan_calls: dict[str, int],
) -> None:
    """Four trees of one skeleton: the first prefixed directly, one trace, three plans applied.

    A trace applies its plan once itself, to check it against the direct prefixing.
    """
    tag = f"t{uuid.uuid4().hex[:8]}"
    trees = [object_tree(tag, size) for size in ("0.1", "0.2", "0.3", "0.4")]
    assert len({naming_skeleton(tree) for tree in trees}) == 1
    seen = []
    for tree in trees:
        assert our_bytes(tree, "obj_", None) == robosuite_bytes(tree, "obj_", None)
        seen.append(dict(plan_calls))
    assert seen == PLANNED_AT_THE_SECOND_COPY


def test_one_tree_asked_again_is_one_skeleton(plan_calls: dict[str, int]) -> None:
    """The same tree prefixed three times is planned once, like three trees of its shape."""
    tree = object_tree(f"t{uuid.uuid4().hex[:8]}", "0.1")
    for _ in range(3):
        assert our_bytes(tree, "p_", None) == robosuite_bytes(tree, "p_", None)
    assert plan_calls == {"traced": 1, "applied": 3}


def test_trees_of_another_skeleton_get_their_own_plan(plan_calls: dict[str, int]) -> None:
    """Two skeletons, two trees each: two traces, and each result is robosuite's."""
    for tag in (f"a{uuid.uuid4().hex[:8]}", f"b{uuid.uuid4().hex[:8]}"):
        for size in ("0.1", "0.2"):
            tree = object_tree(tag, size)
            assert our_bytes(tree, "q_", None) == robosuite_bytes(tree, "q_", None)
    assert plan_calls == {"traced": 2, "applied": 4}


@pytest.mark.parametrize("kept", ["main", "g0", "mat", "hinge", "nothing"])
def test_a_plan_keeps_what_each_call_excludes(kept: str) -> None:
    """Exclusions change from call to call; the plan leaves out exactly what robosuite does."""
    tag = f"t{uuid.uuid4().hex[:8]}"

    def exclude(item: object) -> bool:  # robosuite passes elements and names
        return isinstance(item, str) and item.endswith(kept)

    for index, size in enumerate(("0.1", "0.2", "0.3")):
        tree = object_tree(tag, size)
        chosen = exclude if index == 2 else None
        assert our_bytes(tree, "x_", chosen) == robosuite_bytes(tree, "x_", chosen)


def test_names_already_prefixed_are_kept_by_the_plan() -> None:
    """A tree whose names already start with the prefix keeps them, as robosuite does."""
    tag = f"t{uuid.uuid4().hex[:8]}"
    for size in ("0.1", "0.2", "0.3"):
        tree = object_tree(tag, size)
        assert our_bytes(tree, f"{tag}_", None) == robosuite_bytes(tree, f"{tag}_", None)


def test_trees_that_make_names_are_never_planned(plan_calls: dict[str, int]) -> None:
    """Trees holding a replicate have no skeleton: each is prefixed directly, as robosuite does.

    Three different such trees in a row must not share what one of them taught.
    """
    tag = f"t{uuid.uuid4().hex[:8]}"
    for count, child in ((2, "geom"), (3, "site"), (2, "site")):
        text = (
            f'<body name="{tag}_main"><replicate count="{count}" offset="0.1 0 0">'
            f'<{child} name="{tag}_{child}" size="0.1"/></replicate></body>'
        )
        tree = from_etree(ET.fromstring(text))
        assert naming_skeleton(tree) is None
        for _ in range(2):
            assert our_bytes(tree, "r_", None) == robosuite_bytes(tree, "r_", None)
    assert plan_calls == {"traced": 0, "applied": 0}


def test_typed_and_generic_trees_of_one_naming_are_two_skeletons() -> None:
    """A skeleton includes the node types: a plan of generic nodes never meets typed ones."""
    from mjcf_model import Body, GenericElement, Geom

    geom = GenericElement(tag="geom", attributes={"name": "same_g0"})
    generic = GenericElement(tag="body", attributes={"name": "same_main"}, children=[geom])
    typed = Body(name="same_main", children=[Geom(name="same_g0")])
    assert [type(node).__name__ for node in (generic, typed)] == ["GenericElement", "Body"]
    assert naming_skeleton(generic) != naming_skeleton(typed)
    assert naming.naming_skeleton(typed) == naming_skeleton(
        Body(name="same_main", children=[Geom(name="same_g0", size=[0.2])])
    )
