"""``changes_between``: the semantic diff, on generated models, the corpus and hand-made cases."""

from __future__ import annotations

from pathlib import Path

import attrs
import mujoco
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from mjcf_model import Mujoco, declared_names, find_all, prefixed, with_attributes
from mjcf_model.serializers import dumps, load, loads
from mjcf_model.strategies import models
from mjcf_model.tools.diff import Change, changes_between
from mjcf_model.tree.paths import replaced_at
from mjcf_model.tree.traversal import walk
from tests.conftest import compiling_corpus, corpus_id


@settings(deadline=None)
@given(models())
def test_a_model_equals_its_canonical_rewrite(model: Mujoco) -> None:
    """Formatting, comments dropped or kept, number spelling: none of it is a change."""
    assert changes_between(model, loads(dumps(model, canonical=True))) == []
    assert changes_between(model, model) == []


@settings(deadline=None)
@given(models(), st.data())
def test_one_changed_attribute_is_the_one_change(model: Mujoco, data: st.DataObject) -> None:
    """Changing one attribute of one element is reported as exactly that, at that element."""
    elements = [(path, element) for path, element in walk(model) if path]
    path, element = data.draw(st.sampled_from(elements))
    changed = replaced_at(model, path, [with_attributes(element, {"user_note": "42"})])
    [change] = changes_between(model, changed)
    assert (change.kind, change.attribute, change.old, change.new) == (
        "changed",
        "user_note",
        None,
        "42",
    )
    [back] = changes_between(changed, model)
    assert (back.path, back.old, back.new) == (change.path, "42", None)


@settings(deadline=None)
@given(models())
def test_prefixing_renames_every_named_element(model: Mujoco) -> None:
    """After prefixing, named elements are removed and their prefixed twins added, one for one."""
    declared = sum(len(names) for names in declared_names(model).values())
    changes = changes_between(model, prefixed(model, "p_"))
    removed = [change for change in changes if change.kind == "removed"]
    added = [change for change in changes if change.kind == "added"]
    assert len(removed) == len(added) <= declared
    assert all("='p_" in change.path.rpartition("/")[2] for change in added)
    assert not any("='p_" in change.path for change in removed)
    assert (declared == 0) == (not changes)


@pytest.mark.parametrize("path", compiling_corpus()[::7], ids=corpus_id)
def test_corpus_file_equals_its_canonical_form(path: Path) -> None:
    """A real file and its canonical rewrite have no semantic difference."""
    model = load(path)
    assert changes_between(model, loads(dumps(model, canonical=True))) == []


def test_moves_additions_removals_and_number_spelling() -> None:
    """A hand-checked case: each kind once, reported where it happens."""
    first = loads(
        """<mujoco><worldbody>
             <body name="arm"><geom size="0.10"/><body name="hand"/><site name="s"/></body>
             <geom name="floor" type="plane" size="1 1 .1"/>
           </worldbody></mujoco>"""
    )
    second = loads(
        """<mujoco>
             <worldbody>
               <geom size="1 1 0.1" type="plane" name="floor"/>
               <body name="arm"><geom size=".1" rgba="1 0 0 1"/></body>
               <body name="hand"><camera name="c"/></body>
             </worldbody>
           </mujoco>"""
    )
    assert [str(change) for change in changes_between(first, second)] == [
        "- /mujoco/worldbody/body[@name='arm']/site[@name='s']",
        "> /mujoco/worldbody/geom[@name='floor'] (order changed)",
        "~ /mujoco/worldbody/body[@name='arm']/geom rgba: (not written) -> 1 0 0 1",
        "> /mujoco/worldbody/body[@name='hand'] (was /mujoco/worldbody/body[@name='arm']"
        "/body[@name='hand'])",
        "+ /mujoco/worldbody/body[@name='hand']/camera[@name='c']",
    ]


def test_unnamed_elements_match_by_position_and_text_counts() -> None:
    """The second unnamed geom is geom[2]; text content is compared too (white space aside)."""
    first = loads(
        '<mujoco><worldbody><geom size="1"/><geom size="2"/></worldbody>'
        "<custom><text name='t' data='a'/></custom></mujoco>"
    )
    second = loads(
        '<mujoco><worldbody><geom size="1"/><geom size="3"/></worldbody>'
        "<custom><text name='t' data='b'/></custom></mujoco>"
    )
    changes = changes_between(first, second)
    assert [(c.path, c.attribute, c.old, c.new) for c in changes] == [
        ("/mujoco/worldbody/geom[2]", "size", "2", "3"),
        ("/mujoco/custom/text[@name='t']", "data", "a", "b"),
    ]
    removed = changes_between(first, loads("<mujoco/>"))
    assert [(c.kind, c.path) for c in removed] == [
        ("removed", "/mujoco/worldbody"),
        ("removed", "/mujoco/custom"),
    ]


def test_change_to_dict_is_json_ready() -> None:
    """``to_dict`` leaves out what is not set, and every value is text."""
    change = Change(kind="changed", path="/mujoco/worldbody/geom", attribute="size", old="1")
    assert change.to_dict() == {
        "kind": "changed",
        "path": "/mujoco/worldbody/geom",
        "attribute": "size",
        "old": "1",
    }
    assert attrs.evolve(change, new="2").to_dict()["new"] == "2"
    assert find_all  # the public query still imports beside the diff


def test_order_and_references_count_as_mujoco_counts_them() -> None:
    """Reordered actuators move and references compare as names: both change the model.

    MuJoCo numbers actuators in order, and "1" and "1.0" are two joints.
    """
    base = (
        '<worldbody><body><joint name="1"/><joint name="1.0"/><geom size="1"/></body></worldbody>'
    )
    first = loads(
        f'<mujoco>{base}<actuator><motor name="a" joint="1"/><motor name="b" joint="1"/>'
        "</actuator></mujoco>"
    )
    second = loads(
        f'<mujoco>{base}<actuator><motor name="b" joint="1"/><motor name="a" joint="1.0"/>'
        "</actuator></mujoco>"
    )
    changes = [str(change) for change in changes_between(first, second)]
    assert "~ /mujoco/actuator/motor[@name='a'] joint: 1 -> 1.0" in changes
    moved = [change for change in changes if change.endswith("(order changed)")]
    assert len(changes) == 2 and len(moved) == 1  # one of the two swapped motors moved
    compiled = [mujoco.MjModel.from_xml_string(dumps(model)) for model in (first, second)]
    assert compiled[0].actuator_trnid.tolist() != compiled[1].actuator_trnid.tolist()
