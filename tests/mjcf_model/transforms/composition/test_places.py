"""Tests of ``mjcf_model.transforms.composition.places``."""

from __future__ import annotations

import re
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import mujoco
import numpy as np
import pytest

from mjcf_model import Mujoco, find, find_all, get_attribute, with_attributes
from mjcf_model.bridge.compare import compiled_names
from mjcf_model.errors import MjcfLookupError, MjcfValueError
from mjcf_model.serializers import dumps, load, loads
from mjcf_model.transforms.composition.attaching import AttachKind, attach, attach_all
from mjcf_model.tree.traversal import map_elements
from tests.conftest import FIXTURES, corpus_files

# -- attach() at a site or a frame, with a placement: MuJoCo's MjSpec attach is the referee. ---
#
# Each test attaches with :func:`mjcf_model.attach`, compiles the result, and
# compares it with what ``MjSpec`` compiles after attaching the same two models
# (``spec.attach(child, site=..., frame=...)``, ``site.attach_body``,
# ``frame.attach_body``), the placement set on the frame ``MjSpec`` attaches in.


PLACEMENT = FIXTURES / "placement"
ARM, GRIPPER = PLACEMENT / "arm.xml", PLACEMENT / "gripper.xml"
#: Counts that must be equal before arrays are compared.
COUNTS = ("nbody", "ngeom", "njnt", "nsite", "nu", "nmesh")
#: Compiled arrays compared between our result and MjSpec's.
ARRAYS = (
    "body_parentid",
    "body_pos",
    "body_quat",
    "body_ipos",
    "body_iquat",
    "body_mass",
    "body_inertia",
    "geom_pos",
    "geom_quat",
    "geom_size",
    "geom_rgba",
    "jnt_axis",
    "jnt_pos",
    "jnt_range",
    "dof_damping",
    "site_pos",
    "site_quat",
    "site_size",
)


def _robosuite(relative: str) -> Path:
    return next(path for path in corpus_files() if path.as_posix().endswith(relative))


def _with_absolute_files(path: Path) -> Mujoco:
    """The model at ``path`` with its asset file paths made absolute (compiles from anywhere)."""
    model = load(path)
    assert not any(
        get_attribute(compiler, folder)
        for compiler in find_all(model, "compiler")
        for folder in ("meshdir", "texturedir", "assetdir")
    ), "this helper reads files relative to the model's own folder only"

    def absolute(element: Any, key: str | None, _ancestors: Any) -> Any:
        file = get_attribute(element, "file")
        if key in ("asset/mesh", "asset/texture", "asset/hfield") and isinstance(file, str):
            return with_attributes(element, {"file": str(path.parent / file)})
        return element

    result = map_elements(absolute, model)
    assert isinstance(result, Mujoco)
    return result


def _ours(parent: Mujoco, child: Mujoco, **options: Any) -> mujoco.MjModel:
    return mujoco.MjModel.from_xml_string(dumps(attach(parent, child, prefix="g_", **options)))


def _mjspec(
    parent: Mujoco,
    child: Mujoco,
    at: str | None,
    kind: AttachKind,
    *,
    pos: Sequence[float] | None = None,
    quat: Sequence[float] | None = None,
    euler: Sequence[float] | None = None,
) -> mujoco.MjModel:
    """MjSpec's whole-model attach at ``at``, placed by setting the frame it returns."""
    parent_spec = mujoco.MjSpec.from_string(dumps(parent))
    child_spec = mujoco.MjSpec.from_string(dumps(child))
    if kind == "site":
        frame = parent_spec.attach(child_spec, prefix="g_", site=parent_spec.site(at))
    elif kind == "frame":
        frame = parent_spec.attach(child_spec, prefix="g_", frame=parent_spec.frame(at))
    else:
        holder = parent_spec.worldbody if at is None else parent_spec.body(at)
        frame = parent_spec.attach(child_spec, prefix="g_", frame=holder.add_frame())
    if pos is not None:
        frame.pos = pos
    if quat is not None:
        frame.quat = quat
    if euler is not None:
        frame.alt.type = mujoco.mjtOrientation.mjORIENTATION_EULER
        frame.alt.euler = euler
    return parent_spec.compile()


def _mismatches(
    ours: mujoco.MjModel, theirs: mujoco.MjModel, counts: Sequence[str] = COUNTS
) -> list[str]:
    """Where the two compiled models differ in ``counts``, names or the compared arrays."""
    problems = [
        f"{c}: {getattr(ours, c)} != {getattr(theirs, c)}"
        for c in counts
        if getattr(ours, c) != getattr(theirs, c)
    ]
    if problems:
        return problems
    for kind in ("body", "geom", "jnt", "site"):
        if compiled_names(ours)[kind] != compiled_names(theirs)[kind]:
            problems.append(
                f"{kind} names: {compiled_names(ours)[kind]} != {compiled_names(theirs)[kind]}"
            )
    for field in ARRAYS:
        mine, reference = getattr(ours, field), getattr(theirs, field)
        if not np.allclose(mine, reference, rtol=1e-9, atol=1e-12):
            problems.append(f"{field}:\n{mine}\n!=\n{reference}")
    return problems


SITES = [
    "by_class",
    "quat_over_class_euler",
    "quat_over_class_axisangle",
    "in_frames",
    "attachment_site",
    "xy_site",
    "world_mark",
]


@pytest.mark.parametrize("site", SITES)
def test_attach_at_a_site_compiles_as_mjspec_attaches(site: str) -> None:
    """At a site (class pos, each orientation kind, inside frames, in the world), as MjSpec."""
    arm, gripper = load(ARM), load(GRIPPER)
    ours = _ours(arm, gripper, at=site)
    assert _mismatches(ours, _mjspec(arm, gripper, site, "site")) == []


@pytest.mark.parametrize("frame", ["base_frame", "wrist_mount", "inner_mount"])
def test_attach_at_a_frame_compiles_as_mjspec_attaches(frame: str) -> None:
    """At a world frame, a frame in a body, and a frame in a frame, as MjSpec."""
    arm, gripper = load(ARM), load(GRIPPER)
    ours = _ours(arm, gripper, at=frame)
    assert _mismatches(ours, _mjspec(arm, gripper, frame, "frame")) == []


@pytest.mark.parametrize("body", ["hand", "pedestal", None])
def test_attach_at_a_body_compiles_as_mjspec_attaches(body: str | None) -> None:
    """At a body under a childclass, a plain body and the world, as MjSpec at a new frame there."""
    arm, gripper = load(ARM), load(GRIPPER)
    ours = _ours(arm, gripper, at=body)
    assert _mismatches(ours, _mjspec(arm, gripper, body, "body")) == []


PLACEMENTS: list[tuple[str | None, AttachKind, dict[str, Sequence[float]]]] = [
    ("attachment_site", "site", {"pos": (0.01, -0.02, 0.05), "quat": (0.8, 0.1, -0.3, 0.2)}),
    ("in_frames", "site", {"euler": (15, -30, 60)}),
    ("inner_mount", "frame", {"pos": (0, 0, 0.1), "euler": (90, 0, 10)}),
    ("hand", "body", {"quat": (0, 0, 0, 1)}),
    (None, "body", {"pos": (0.3, 0.2, 0.1), "euler": (0, 45, 0)}),
]


@pytest.mark.parametrize(("at", "kind", "placement"), PLACEMENTS)
def test_placement_compiles_as_mjspec_frame_pose(
    at: str | None, kind: AttachKind, placement: dict[str, Sequence[float]]
) -> None:
    """pos, quat and euler (degrees, zyx from the parent) place the child as MjSpec's frame."""
    arm, gripper = load(ARM), load(GRIPPER)
    ours = _ours(arm, gripper, at=at, at_kind=kind if at else None, **placement)
    assert _mismatches(ours, _mjspec(arm, gripper, at, kind, **placement)) == []


def test_attach_all_at_a_site_places_every_child_as_mjspec() -> None:
    """Several children attached in one pass at a placed site compile as MjSpec attaching each."""
    arm, gripper = load(ARM), load(GRIPPER)
    pos, euler = (0.0, 0.0, 0.05), (0.0, 0.0, 30.0)
    scene = attach_all(arm, [(gripper, "g_"), (gripper, "h_")], at="xy_site", pos=pos, euler=euler)
    ours = mujoco.MjModel.from_xml_string(dumps(scene))
    parent_spec = mujoco.MjSpec.from_string(dumps(arm))
    for prefix in ("g_", "h_"):
        child_spec = mujoco.MjSpec.from_string(dumps(gripper))
        frame = parent_spec.attach(child_spec, prefix=prefix, site=parent_spec.site("xy_site"))
        frame.pos = pos
        frame.alt.type = mujoco.mjtOrientation.mjORIENTATION_EULER
        frame.alt.euler = euler
    assert _mismatches(ours, parent_spec.compile()) == []


def test_a_name_of_two_kinds_needs_at_kind() -> None:
    """A name both a site and a frame have is refused until at_kind says which; each then works."""
    arm, gripper = load(ARM), load(GRIPPER)
    with pytest.raises(MjcfLookupError, match=r"site and a frame named 'mount'.*at_kind="):
        attach(arm, gripper, at="mount", prefix="g_")
    for kind in ("site", "frame"):
        ours = _ours(arm, gripper, at="mount", at_kind=kind)
        assert _mismatches(ours, _mjspec(arm, gripper, "mount", kind)) == []


def test_an_unknown_name_lists_bodies_frames_and_sites() -> None:
    """The error for an unknown ``at`` names every body, frame and site the parent has."""
    spec = mujoco.MjSpec.from_file(str(ARM))
    compiled = spec.compile()
    bodies = compiled_names(compiled)["body"][1:]  # body 0 is MuJoCo's world
    existing = [n for n in [*bodies, *compiled_names(compiled)["site"]] if n]
    existing += [frame.name for frame in spec.frames]
    with pytest.raises(MjcfLookupError) as raised:
        attach(load(ARM), load(GRIPPER), at="elsewhere", prefix="g_")
    assert "no body named 'elsewhere'" in str(raised.value)
    for name in existing:
        assert repr(name) in str(raised.value)
    with pytest.raises(MjcfLookupError, match=r"no site named 'hand'"):
        attach(load(ARM), load(GRIPPER), at="hand", at_kind="site", prefix="g_")


def test_bad_placements_are_refused() -> None:
    """Both quat and euler, or a vector of the wrong length, raise MjcfValueError."""
    arm, gripper = load(ARM), load(GRIPPER)
    with pytest.raises(MjcfValueError, match="quat or as euler"):
        attach(arm, gripper, at="hand", prefix="g_", quat=(1, 0, 0, 0), euler=(0, 0, 0))
    with pytest.raises(MjcfValueError):
        attach(arm, gripper, at="hand", prefix="g_", pos=(0, 1))


def test_a_site_placed_by_fromto_is_refused() -> None:
    """MjSpec attaches at a fromto site's unset pose, not where it compiles: refused, named."""
    site = '<site name="rod" type="capsule" size="0.01" fromto="0 0 0 0.1 0.1 0.1"/>'
    parent = loads(f'<mujoco><worldbody><body name="b">{site}</body></worldbody></mujoco>')
    unplaced = mujoco.MjModel.from_xml_path(str(GRIPPER)).body("palm")
    spec_body = _mjspec(parent, load(GRIPPER), "rod", "site").body("g_palm")
    assert np.allclose(spec_body.pos, unplaced.pos), "MjSpec no longer ignores fromto"
    assert np.allclose(spec_body.quat, unplaced.quat), "MjSpec no longer ignores fromto"
    with pytest.raises(MjcfValueError, match=r"site 'rod'.*fromto"):
        attach(parent, load(GRIPPER), at="rod", prefix="g_")


def _qpos_by_joint(model: mujoco.MjModel, key: int | None) -> dict[str, float]:
    values = model.qpos0 if key is None else model.key_qpos[key]
    return {model.jnt(j).name: float(values[model.jnt_qposadr[j]]) for j in range(model.njnt)}


def test_keyframes_survive_attaching_at_a_site() -> None:
    """Each key keeps its own joints' values; the other model's joints get their qpos0."""
    arm_alone = mujoco.MjModel.from_xml_path(str(ARM))
    gripper_alone = mujoco.MjModel.from_xml_path(str(GRIPPER))
    scene = _ours(load(ARM), load(GRIPPER), at="attachment_site")
    home = _qpos_by_joint(scene, scene.key("home").id)
    ajar = _qpos_by_joint(scene, scene.key("g_ajar").id)
    for name, value in _qpos_by_joint(arm_alone, arm_alone.key("home").id).items():
        assert home[name] == pytest.approx(value)
    for name, value in _qpos_by_joint(arm_alone, None).items():
        assert ajar[name] == pytest.approx(value)
    for name, value in _qpos_by_joint(gripper_alone, gripper_alone.key("ajar").id).items():
        assert ajar[f"g_{name}"] == pytest.approx(value)
    for name, value in _qpos_by_joint(gripper_alone, None).items():
        assert home[f"g_{name}"] == pytest.approx(value)


XARM = "robosuite/models/assets/robots/xarm7/robot.xml"
#: robosuite's own xarm7 gripper file does not compile alone (``group`` on a ``<default>``);
#: its panda gripper does, and reads the same under the arm's compiler (quats, slides).
PANDA_GRIPPER = "robosuite/models/assets/grippers/panda_gripper.xml"


@pytest.mark.parametrize("site", ["ee", "ee_x", "ee_y", "ee_z"])
def test_robosuite_gripper_at_the_arm_sites_compiles_as_mjspec(site: str) -> None:
    """A robosuite gripper at each site of the xarm7 hand compiles as MjSpec's site attach."""
    arm = _with_absolute_files(_robosuite(XARM))
    gripper = _with_absolute_files(_robosuite(PANDA_GRIPPER))
    ours = _ours(arm, gripper, at=site)
    assert _mismatches(ours, _mjspec(arm, gripper, site, "site")) == []


def test_robosuite_gripper_placed_at_a_site_matches_attach_body() -> None:
    """A placed gripper equals MjSpec's attach_body at a frame with that pose at the site."""
    arm = _with_absolute_files(_robosuite(XARM))
    gripper = _with_absolute_files(_robosuite(PANDA_GRIPPER))
    pos, quat = (0.0, 0.01, 0.02), (0.5, 0.5, -0.5, 0.5)
    ours = _ours(arm, gripper, at="ee_x", pos=pos, quat=quat)
    parent_spec = mujoco.MjSpec.from_string(dumps(arm))
    child_spec = mujoco.MjSpec.from_string(dumps(gripper))
    site = parent_spec.site("ee_x")
    outer = parent_spec.body("right_hand").add_frame()
    outer.pos, outer.quat, outer.alt = site.pos, site.quat, site.alt
    inner = parent_spec.body("right_hand").add_frame(outer)
    inner.pos, inner.quat = pos, quat
    roots = child_spec.worldbody.bodies
    assert len(roots) == 1, "the gripper has one root body"
    inner.attach_body(roots[0], "g_", "")
    # attach_body moves the body tree only: the gripper's actuators stay behind.
    without_actuators = [c for c in COUNTS if c != "nu"]
    assert _mismatches(ours, parent_spec.compile(), without_actuators) == []


def test_attaching_deep_in_a_tree_needs_no_recursion() -> None:
    """A body 1,200 levels deep takes a child: the tree is rebuilt without recursion."""
    depth = 1200
    text = "".join(f'<body name="b{i}">' for i in range(depth)) + "</body>" * depth
    parent = loads(f"<mujoco><worldbody>{text}</worldbody></mujoco>")
    child = loads('<mujoco><worldbody><body name="c"><geom size="1"/></body></worldbody></mujoco>')
    scene = attach(parent, child, at=f"b{depth - 1}", prefix="x_")
    deepest = find(scene, "body", name=f"b{depth - 1}")
    assert deepest is not None and [b.name for b in deepest.bodies] == ["x_c"]


# -- attach() under a body's ``childclass``: the innermost placing frame resets the class. -----
#
# A ``childclass`` of the body holding the attach point would reach the child's
# elements; ``MjSpec`` keeps them in the child's own classes. So the frame that
# already places the child (the site's pose, or the placement asked for) sets
# ``childclass="main"``: no extra frame is added for it.


#: Class ``red`` colours geoms; the body ``b`` gives it to everything it holds.
PARENT_CHILDCLASS_RESET = """<mujoco>
  <default><default class="red"><geom rgba="1 0 0 1"/></default></default>
  <worldbody><body name="b" pos="0 1 0" childclass="red">
    <geom size="0.2"/><site name="s" pos="0 0 0.1"/>
  </body></worldbody>
</mujoco>"""
CHILD_CHILDCLASS_RESET = (
    '<mujoco><worldbody><body name="palm"><geom size="0.1"/></body></worldbody></mujoco>'
)
CASES: dict[str, dict[str, Any]] = {
    "at the site": {"at": "s"},
    "at the body, placed": {"at": "b", "pos": (0, 0, 0.1)},
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_the_placing_frame_itself_resets_the_body_childclass(case: str) -> None:
    """One frame places the child and sets childclass main; the child keeps its own colours."""
    scene = attach(
        loads(PARENT_CHILDCLASS_RESET), loads(CHILD_CHILDCLASS_RESET), prefix="g_", **CASES[case]
    )
    frames = find_all(scene, "frame")
    assert [(get_attribute(f, "pos"), get_attribute(f, "childclass")) for f in frames] == [
        ((0, 0, 0.1), "main")
    ]
    compiled = mujoco.MjModel.from_xml_string(dumps(scene))
    data = mujoco.MjData(compiled)
    mujoco.mj_kinematics(compiled, data)
    assert np.allclose(data.body("g_palm").xpos, [0, 1, 0.1])  # b + the site's pos
    palm_geom = compiled.body_geomadr[compiled.body("g_palm").id]
    alone = mujoco.MjModel.from_xml_string(CHILD_CHILDCLASS_RESET)
    assert np.allclose(compiled.geom_rgba[palm_geom], alone.geom_rgba[0])


# -- attach() at a site or frame inside a frame with a ``childclass``: that class stays behind.
#
# MjSpec (and so :func:`mjcf_model.attach`) puts the child at the end of the body
# holding the target, in frames that copy the poses on the way; a ``childclass``
# of a frame around the target reaches only that frame's own children, so the
# frames wrapping the child copy poses only and set no class.


#: Class ``red`` colours geoms; the frame ``outer`` gives it to what it holds.
PARENT_FRAME_CHILDCLASS = """<mujoco>
  <default><default class="red"><geom rgba="1 0 0 1"/></default></default>
  <worldbody><body name="b" pos="0 1 0">
    <frame name="outer" childclass="red" pos="0 0 1">{target}</frame>
  </body></worldbody>
</mujoco>"""
TARGETS = {
    "site": '<site name="here" pos="0 0 0.1"/>',
    "frame": '<frame name="here" pos="0 0 0.1"/>',
}
CHILD_FRAME_CHILDCLASS = (
    '<mujoco><worldbody><body name="palm"><geom size="0.1"/></body></worldbody></mujoco>'
)


@pytest.mark.parametrize("kind", sorted(TARGETS))
def test_a_frame_childclass_around_the_target_does_not_reach_the_child(kind: str) -> None:
    """The wrapping frames set no childclass; the child sits at the target, in its own colours."""
    text = PARENT_FRAME_CHILDCLASS.format(target=TARGETS[kind])
    scene = attach(loads(text), loads(CHILD_FRAME_CHILDCLASS), at="here", prefix="g_")
    frames = [f for f in find_all(scene, "frame") if get_attribute(f, "name") is None]
    assert [get_attribute(f, "childclass") for f in frames] == [None, None]
    compiled = mujoco.MjModel.from_xml_string(dumps(scene))
    data = mujoco.MjData(compiled)
    mujoco.mj_kinematics(compiled, data)
    assert np.allclose(data.body("g_palm").xpos, [0, 1, 1.1])  # b + outer + here
    default_rgba = mujoco.MjModel.from_xml_string(CHILD_FRAME_CHILDCLASS).geom_rgba[0]
    assert np.allclose(compiled.geom_rgba[0], default_rgba)


# -- attach() refusing a placement or an attach point: the error type and what the message
#    tells.
#
# Each model here is a few lines of MJCF, so the names an error lists are read off
# the text; MuJoCo compiles each parent, so every name is one MuJoCo accepts.


#: A parent with two bodies, a frame and a site named ``mount`` and one more site.
PARENT_REFUSALS = """<mujoco><worldbody>
  <body name="base">
    <frame name="mount" pos="0 0 0.1"/>
    <site name="mount" pos="0 0.1 0"/>
    <body name="arm" pos="0 0 0.5"><site name="tip"/></body>
  </body>
</worldbody></mujoco>"""
#: A child with one body.
CHILD_REFUSALS = '<mujoco><worldbody><body name="palm"/></worldbody></mujoco>'


def _parent() -> Any:
    mujoco.MjModel.from_xml_string(PARENT_REFUSALS)  # MuJoCo accepts every name listed below
    return loads(PARENT_REFUSALS)


def test_both_quat_and_euler_are_refused_in_full_words() -> None:
    """Both quat and euler: MjcfValueError telling to give the orientation one way only."""
    with pytest.raises(
        MjcfValueError, match=r"^give the child's orientation as quat or as euler, not both$"
    ):
        attach(_parent(), loads(CHILD_REFUSALS), at="arm", quat=(1, 0, 0, 0), euler=(0, 0, 0))


def test_an_unknown_at_kind_is_refused_naming_the_three_kinds() -> None:
    """at_kind other than body, frame or site: MjcfValueError listing the three and the value."""
    kind: Any = "geom"
    with pytest.raises(
        MjcfValueError, match=r"^at_kind must be 'body', 'frame' or 'site', not 'geom'$"
    ):
        attach(_parent(), loads(CHILD_REFUSALS), at="arm", at_kind=kind)


def test_a_name_of_two_kinds_lists_the_at_kind_values_to_choose() -> None:
    """A frame and a site of one name: the message offers at_kind='frame' or 'site'."""
    expected = (
        "the parent has a frame and a site named 'mount'; say which with at_kind='frame' or 'site'"
    )
    with pytest.raises(MjcfLookupError, match=f"^{re.escape(expected)}$"):
        attach(_parent(), loads(CHILD_REFUSALS), at="mount")


def test_an_unknown_name_lists_the_bodies_frames_and_sites_by_kind() -> None:
    """An unknown ``at``: the message lists its bodies, frames and sites, sorted, in plain words."""
    listed = (
        "its bodies are ['arm', 'base'], its frames are ['mount'], its sites are ['mount', 'tip']"
    )
    expected = f"the parent has no body named 'elsewhere' (nor a frame or site); {listed}"
    with pytest.raises(MjcfLookupError, match=f"^{re.escape(expected)}$"):
        attach(_parent(), loads(CHILD_REFUSALS), at="elsewhere")
    expected = f"the parent has no site named 'arm'; {listed}"
    with pytest.raises(MjcfLookupError, match=f"^{re.escape(expected)}$"):
        attach(_parent(), loads(CHILD_REFUSALS), at="arm", at_kind="site")


@pytest.mark.parametrize("target", ["site", "frame"])
def test_a_target_inside_a_replicate_is_refused_naming_it(target: str) -> None:
    """A site or frame inside a <replicate> (copied, so not one place): MjcfValueError naming it."""
    text = (
        '<mujoco><worldbody><body name="b"><replicate count="2" offset="0.1 0 0">'
        f'<{target} name="here"/></replicate></body></worldbody></mujoco>'
    )
    mujoco.MjModel.from_xml_string(text)  # MuJoCo accepts the parent
    with pytest.raises(
        MjcfValueError, match=r"^cannot attach at 'here': it is inside a <replicate>$"
    ):
        attach(loads(text), loads(CHILD_REFUSALS), at="here")


def test_a_site_placed_by_fromto_is_refused_saying_what_to_give_instead() -> None:
    """A fromto site: MjcfValueError saying MjSpec ignores it; give pos and an orientation."""
    site = '<site name="rod" type="capsule" size="0.01" fromto="0 0 0 0.1 0.1 0.1"/>'
    text = f'<mujoco><worldbody><body name="b">{site}</body></worldbody></mujoco>'
    mujoco.MjModel.from_xml_string(text)  # MuJoCo accepts the parent
    expected = (
        "cannot attach at site 'rod': its pose comes from 'fromto' (MjSpec would ignore it); "
        "give the site pos and an orientation instead"
    )
    with pytest.raises(MjcfValueError, match=f"^{re.escape(expected)}$"):
        attach(loads(text), loads(CHILD_REFUSALS), at="rod")
