"""Prefixing part of a model: chosen namespaces, excluded names, partial renaming maps.

MuJoCo is the referee: each renamed model is compiled and the names MuJoCo gives
are compared with the original's, prefixed or mapped by the rule asked for
(names outside the chosen namespaces and excluded names stay as they are).
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import pytest

from mjcf_model.bridge.compare import compile_text_beside, compiled_names, model_differences
from mjcf_model.nodes.base import get_attribute
from mjcf_model.transforms.naming.renaming import prefix_map, prefixed, renamed
from serializers import dumps, load, loads
from tests.support.oracles import RENAMING_FIELDS, prefix_problems

ARM = """<mujoco><asset><material name="red" rgba="1 0 0 1"/></asset><worldbody>
  <body name="arm"><joint name="elbow"/><geom name="upper" size="0.1" material="red"/>
    <body name="hand" pos="0 0 0.3"><joint name="wrist"/><geom name="palm" size="0.05"/></body>
  </body></worldbody>
  <actuator><motor name="lift" joint="elbow"/><motor name="turn" joint="wrist"/></actuator>
</mujoco>"""

#: MuJoCo's kinds of names, and the namespace of each.
NAMESPACE_OF_KIND = {
    "body": "body",
    "jnt": "joint",
    "geom": "geom",
    "mat": "material",
    "actuator": "actuator",
}


def mujoco_names(model: mujoco.MjModel) -> dict[str, list[str]]:
    """The names MuJoCo gives, by namespace (the kinds of ``NAMESPACE_OF_KIND``)."""
    names = compiled_names(model)
    return {namespace: names[kind] for kind, namespace in NAMESPACE_OF_KIND.items()}


def expected_names(
    original: mujoco.MjModel, prefix: str, namespaces: set[str], excluded: set[str]
) -> dict[str, list[str]]:
    """The original's names with ``prefix`` in the chosen namespaces, except excluded ones."""
    return {
        namespace: [
            prefix + name
            if namespace in namespaces and name not in excluded and name not in ("", "world")
            else name
            for name in names
        ]
        for namespace, names in mujoco_names(original).items()
    }


def test_prefix_map_lists_the_chosen_names_mujoco_declares() -> None:
    """The map holds each chosen namespace's names but excluded ones; none with nothing left."""
    original = mujoco.MjModel.from_xml_string(ARM)
    model = loads(ARM)
    chosen, excluded = {"body", "geom", "material"}, {"hand", "upper", "red"}
    expected = {
        namespace: {name: "p_" + name for name in names if name not in excluded | {"world"}}
        for namespace, names in mujoco_names(original).items()
        if namespace in chosen
    }
    expected = {namespace: names for namespace, names in expected.items() if names}
    assert expected == {"body": {"arm": "p_arm"}, "geom": {"palm": "p_palm"}}
    mapping = prefix_map(model, "p_", namespaces=chosen, exclude=excluded)
    assert mapping == expected
    changed = mujoco.MjModel.from_xml_string(dumps(renamed(model, mapping)))
    assert model_differences(original, changed, ignore=RENAMING_FIELDS) == []
    assert mujoco_names(changed) == expected_names(original, "p_", chosen, excluded)


@pytest.mark.parametrize(
    ("namespaces", "excluded"),
    [({"body", "joint"}, set()), ({"body", "joint", "geom"}, {"upper", "wrist"})],
    ids=["namespaces", "excluded"],
)
def test_prefixing_undeclared_references_keeps_what_is_not_chosen(
    namespaces: set[str], excluded: set[str]
) -> None:
    """With ``undeclared=True`` too, only chosen namespaces change, and excluded names stay."""
    original = mujoco.MjModel.from_xml_string(ARM)
    new = prefixed(loads(ARM), "p_", namespaces=namespaces, exclude=excluded, undeclared=True)
    changed = mujoco.MjModel.from_xml_string(dumps(new))
    assert model_differences(original, changed, ignore=RENAMING_FIELDS) == []
    assert mujoco_names(changed) == expected_names(original, "p_", namespaces, excluded)


@pytest.mark.parametrize(
    "mapping",
    [
        {"arm": "base", "elbow": "shoulder"},
        {"body": {"arm": "base"}, "joint": {"elbow": "shoulder"}},
    ],
    ids=["flat", "by-namespace"],
)
def test_names_a_renaming_does_not_mention_stay(mapping: dict[str, object]) -> None:
    """Names missing from the map (geoms, the material, the motors, hand, wrist) keep theirs."""
    original = mujoco.MjModel.from_xml_string(ARM)
    changed = mujoco.MjModel.from_xml_string(dumps(renamed(loads(ARM), mapping)))  # type: ignore[arg-type]
    assert model_differences(original, changed, ignore=RENAMING_FIELDS) == []
    expected = mujoco_names(original)
    expected["body"] = ["world", "base", "hand"]
    expected["joint"] = ["shoulder", "wrist"]
    assert mujoco_names(changed) == expected


def test_excluding_a_name_still_prefixes_attached_names(tmp_path: Path) -> None:
    """With every namespace and an exclusion, the attach prefix gains the prefix as well."""
    (tmp_path / "child.xml").write_text(
        '<mujoco model="kid"><worldbody><body name="palm"><geom size="0.1"/>'
        '<body name="x1" pos="0 0 0.3"><geom size="0.05"/></body></body></worldbody></mujoco>',
        encoding="utf-8",
    )
    path = tmp_path / "scene.xml"
    path.write_text(
        """<mujoco><asset><model file="child.xml"/></asset><worldbody>
          <body name="mount"><geom name="base" size="0.1"/>
            <attach model="kid" body="palm" prefix="g_"/></body>
        </worldbody><contact><exclude body1="mount" body2="g_x1"/></contact></mujoco>""",
        encoding="utf-8",
    )
    original = mujoco.MjModel.from_xml_path(str(path))
    changed = compile_text_beside(dumps(prefixed(load(path), "p_", exclude={"base"})), path)
    assert prefix_problems(original, changed, "p_", kept={"base"}) == []


def test_excluding_with_a_namespace_that_declares_nothing() -> None:
    """A camera aimed at the world body (no body is declared) compiles after prefixing."""
    text = """<mujoco><worldbody><geom name="floor" type="plane" size="1 1 0.1"/>
      <camera name="eye" mode="targetbody" target="world"/></worldbody></mujoco>"""
    original = mujoco.MjModel.from_xml_string(text)
    changed = mujoco.MjModel.from_xml_string(dumps(prefixed(loads(text), "p_", exclude={"x"})))
    assert prefix_problems(original, changed, "p_") == []
    assert changed.cam_targetbodyid[0] == 0


def test_a_name_list_renaming_leaves_alone_is_the_input_node() -> None:
    """A flex's body list with nothing renamed stays the same node (unchanged parts are shared).

    Its two spaces are kept too: only a list holding a renamed name is written again.
    """
    text = """<mujoco><worldbody>
      <body name="b1"><joint type="free"/><geom size="0.1"/></body>
      <body name="b2" pos="0 1 0"><joint type="free"/><geom size="0.1"/></body></worldbody>
      <deformable><flex name="f" dim="1" body="b1  b2" element="0 1" vertex="0 0 0 0 0 0"/>
      </deformable></mujoco>"""
    model = loads(text)
    flex = model.deformable.children[0]
    unchanged = renamed(model, {"geom": {"nothing": "else"}, "body": {"b3": "b4"}})
    assert unchanged.deformable.children[0] is flex
    changed = renamed(model, {"body": {"b1": "z1"}})
    assert get_attribute(changed.deformable.children[0], "body") == "z1 b2"
    names = compiled_names(mujoco.MjModel.from_xml_string(dumps(changed)))["body"]
    assert names == ["world", "z1", "b2"]
