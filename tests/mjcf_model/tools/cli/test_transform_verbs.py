"""Tests of ``mjcf_model.tools.cli.transform_verbs``."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import mujoco
import numpy as np

from mjcf_model.bridge.compare import model_differences, path_fields
from tests.support.cli import UNTIDY, _files, run

# -- ``mjcf-model compose`` places each part: a process, real files, MuJoCo's compiled poses. --
#
# Each expected pose is computed from the part compiled alone (``mj_kinematics`` at
# ``qpos0``), moved by the placement with MuJoCo's own quaternion functions.


def _poses(model: mujoco.MjModel) -> mujoco.MjData:
    """``model``'s data after ``mj_kinematics`` at ``qpos0``."""
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    return data


def _quat(quat: Sequence[float] | None = None, euler_degrees: Sequence[float] = ()) -> np.ndarray:
    """A unit quaternion: ``quat`` normalized, or MuJoCo's from z-y-x Euler angles in degrees."""
    result = np.zeros(4)
    if quat is not None:
        result[:] = quat
        mujoco.mju_normalize4(result)
    else:
        mujoco.mju_euler2Quat(result, np.radians(euler_degrees), "zyx")
    return result


def _assert_placed(
    scene: mujoco.MjModel,
    alone_path: Path,
    prefix: str,
    pos: Sequence[float],
    quat: np.ndarray,
    frame: tuple[np.ndarray, np.ndarray] = (np.zeros(3), np.array([1.0, 0, 0, 0])),
) -> None:
    """Each body of the part alone is in ``scene`` (prefixed), moved by ``frame`` then the pose."""
    alone = mujoco.MjModel.from_xml_path(str(alone_path))
    before, after = _poses(alone), _poses(scene)
    place_quat, place_pos = np.zeros(4), np.zeros(3)
    mujoco.mju_mulQuat(place_quat, frame[1], quat)
    mujoco.mju_rotVecQuat(place_pos, np.asarray(pos, dtype=float), frame[1])
    place_pos += frame[0]
    for body in range(1, alone.nbody):
        name = prefix + alone.body(body).name
        expected_pos, expected_quat = np.zeros(3), np.zeros(4)
        mujoco.mju_rotVecQuat(expected_pos, before.xpos[body], place_quat)
        mujoco.mju_mulQuat(expected_quat, place_quat, before.xquat[body])
        assert np.allclose(after.body(name).xpos, expected_pos + place_pos), name
        found = after.body(name).xquat
        assert np.allclose(found, expected_quat) or np.allclose(found, -expected_quat), name


def test_compose_places_free_bodies(tmp_path: Path) -> None:
    """Two copies of a free box, one moved (negative numbers), one moved and turned by euler=."""
    files = _files(tmp_path)
    scene_path = tmp_path / "scene.xml"
    done = run(
        "compose",
        str(scene_path),
        str(files["base"]),
        f"{files['free']}:a_",
        "pos=-1,0.5,0",
        f"{files['free']}:b_",
        "pos=1,-0.25,0.2",
        "euler=30,20,10",
    )
    assert done.returncode == 0, done.stderr
    scene = mujoco.MjModel.from_xml_path(str(scene_path))
    _assert_placed(scene, files["free"], "a_", (-1, 0.5, 0), _quat((1, 0, 0, 0)))
    _assert_placed(scene, files["free"], "b_", (1, -0.25, 0.2), _quat(euler_degrees=(30, 20, 10)))


def test_compose_places_fixed_arms(tmp_path: Path) -> None:
    """Three arms: moved, moved and turned by quat=, and at a body turned by euler=.

    The last is placed relative to the base's ``table`` body, as MuJoCo compiles it.
    """
    files = _files(tmp_path)
    scene_path = tmp_path / "scene.xml"
    arm = files["arm"]
    done = run(
        "compose",
        str(scene_path),
        str(files["base"]),
        f"{arm}:left_",
        "pos=-0.5,0,0",
        f"{arm}:right_",
        "pos=0.5,0,0",
        "quat=1,0,0,1",
        f"{arm}:top_@table",
        "pos=0,0.1,0.02",
        "euler=-90,0,15",
    )
    assert done.returncode == 0, done.stderr
    scene = mujoco.MjModel.from_xml_path(str(scene_path))
    _assert_placed(scene, arm, "left_", (-0.5, 0, 0), _quat((1, 0, 0, 0)))
    _assert_placed(scene, arm, "right_", (0.5, 0, 0), _quat((1, 0, 0, 1)))
    base = _poses(mujoco.MjModel.from_xml_path(str(files["base"]))).body("table")
    table = (base.xpos.copy(), base.xquat.copy())
    _assert_placed(scene, arm, "top_", (0, 0.1, 0.02), _quat(euler_degrees=(-90, 0, 15)), table)


def test_compose_keyframes_separate(tmp_path: Path) -> None:
    """``--keyframes separate`` keeps each arm's key under its prefixed name, setting that arm."""
    files = _files(tmp_path)
    scene_path = tmp_path / "scene.xml"
    arm = files["arm"]
    words = [f"{arm}:left_", "pos=-0.5,0,0", f"{arm}:right_", "pos=0.5,0,0"]
    done = run("compose", str(scene_path), str(files["base"]), *words, "--keyframes", "separate")
    assert done.returncode == 0, done.stderr
    scene = mujoco.MjModel.from_xml_path(str(scene_path))
    alone = mujoco.MjModel.from_xml_path(str(arm))
    bent = alone.key("bent").qpos
    for prefix in ("left_", "right_"):
        key = scene.key(f"{prefix}bent").qpos
        for joint in ("shoulder", "elbow"):
            address = scene.joint(prefix + joint).qposadr[0]
            assert key[address] == bent[alone.joint(joint).qposadr[0]], (prefix, joint)


def test_compose_keyframes_merged(tmp_path: Path) -> None:
    """``--keyframes merged`` writes one ``bent`` key setting both arms, the free box as placed."""
    files = _files(tmp_path)
    scene_path = tmp_path / "scene.xml"
    arm = files["arm"]
    words = [f"{files['free']}:box_", "pos=0,1,0", f"{arm}:left_", "pos=-0.5,0,0"]
    words += [f"{arm}:right_", "pos=0.5,0,0", "euler=0,0,90"]
    done = run("compose", str(scene_path), str(files["base"]), *words, "--keyframes", "merged")
    assert done.returncode == 0, done.stderr
    scene = mujoco.MjModel.from_xml_path(str(scene_path))
    alone = mujoco.MjModel.from_xml_path(str(arm))
    assert scene.nkey == 1 and scene.key(0).name == "bent"
    bent = alone.key("bent").qpos
    for prefix in ("left_", "right_"):
        for joint in ("shoulder", "elbow"):
            address = scene.joint(prefix + joint).qposadr[0]
            assert scene.key_qpos[0, address] == bent[alone.joint(joint).qposadr[0]]
    box = scene.joint(scene.body("box_box").jntadr[0]).qposadr[0]
    assert np.array_equal(scene.key_qpos[0, box : box + 7], scene.qpos0[box : box + 7])


def test_compose_help_shows_placement() -> None:
    """``compose --help`` shows the placement words, the units of euler= and --keyframes."""
    done = run("compose", "--help")
    assert done.returncode == 0, done.stderr
    for shown in ("pos=X,Y,Z", "quat=W,X,Y,Z", "euler=A,B,C", "eulerseq", "angle units"):
        assert shown in done.stdout
    assert "--keyframes {separate,merged}" in done.stdout


# -- The verbs of ``mjcf-model`` run as a user runs them: a process, real files, exit codes. ---


def test_compose_robots_from_different_folders(tmp_path: Path) -> None:
    """Robosuite's arena, a robot and an object, each from its own folder, into one scene."""
    assets = Path(__import__("robosuite").__file__).parent / "models" / "assets"
    scene = tmp_path / "out" / "scene.xml"
    scene.parent.mkdir()
    done = run(
        "compose",
        str(scene),
        str(assets / "arenas" / "table_arena.xml"),
        f"{assets / 'robots' / 'panda' / 'robot.xml'}:robot0_",
        f"{assets / 'objects' / 'can.xml'}:can_",
        "--export",
        str(tmp_path / "exported"),
    )
    assert done.returncode == 0, done.stderr
    compiled = mujoco.MjModel.from_xml_path(str(scene))
    assert compiled.body("robot0_link7").id > 0 and compiled.body("can_object").id > 0
    exported = tmp_path / "exported" / "table_arena.xml"
    again = mujoco.MjModel.from_xml_path(str(exported))
    assert model_differences(compiled, again, ignore=path_fields()) == []
    assert all(p.is_relative_to(tmp_path / "exported") for p in (tmp_path / "exported").rglob("*"))


def test_compose_failure_writes_nothing(tmp_path: Path) -> None:
    """A scene MuJoCo rejects (a name twice) is not written; the message says why."""
    arm = tmp_path / "arm.xml"
    arm.write_text(UNTIDY)
    scene = tmp_path / "scene.xml"
    done = run("compose", str(scene), str(arm), str(arm))
    assert done.returncode == 2
    assert done.stderr.startswith("mjcf-model compose: ")
    assert not scene.exists()
    unknown = run("compose", str(scene), str(arm), f"{arm}:b_", "--at", "nowhere")
    assert unknown.returncode == 2 and "nowhere" in unknown.stderr and not scene.exists()


def test_what_is_written_is_reported_in_command_line_words(tmp_path: Path) -> None:
    """compose, prefix and scale say what they wrote and what MuJoCo compiles it to.

    The counts are MuJoCo's; a name clash is advised in options (FILE:PREFIX,
    --keyframes), not Python arguments; nothing is said when the model itself goes to
    standard output.
    """
    files = _files(tmp_path)
    scene_path = tmp_path / "scene.xml"
    arm = files["arm"]
    words = [f"{arm}:left_", "pos=-0.5,0,0", f"{arm}:right_", "pos=0.5,0,0"]
    done = run("compose", str(scene_path), str(files["base"]), *words)
    assert done.returncode == 0, done.stderr
    scene = mujoco.MjModel.from_xml_path(str(scene_path))
    counts = (
        f"{scene.nbody - 1} bodies, {scene.njnt} joints, {scene.ngeom} geoms, "
        f"{scene.nu} actuators, {scene.nkey} keyframes"
    )
    assert done.stdout == (
        f"wrote {scene_path}: 2 parts attached to {files['base']}; MuJoCo compiles it: {counts}\n"
    )
    renamed = tmp_path / "renamed.xml"
    prefixed = run("prefix", str(arm), "l_", "-o", str(renamed))
    assert prefixed.returncode == 0 and prefixed.stdout.startswith(
        f"wrote {renamed}: {arm} prefixed 'l_': "
    )
    assert run("prefix", str(arm), "l_").stdout.startswith("<mujoco")  # the model alone
    big = tmp_path / "big.xml"
    scaled = run("scale", str(arm), "--factor", "2", "-o", str(big))
    assert scaled.stdout.startswith(f"wrote {big}: {arm} scaled by 2.0: ")
    clash = run("compose", str(tmp_path / "clash.xml"), str(arm), str(arm))
    assert clash.returncode == 2
    assert "give the part a prefix (FILE:PREFIX)" in clash.stderr
    assert "(or keys of one name with --keyframes merged)" in clash.stderr
    assert "keyframes='merged'" not in clash.stderr and "attach it with" not in clash.stderr


def test_version_names_this_package_and_mujoco() -> None:
    """--version prints the installed versions of mjcf-model and MuJoCo."""
    import importlib.metadata

    done = run("--version")
    assert done.returncode == 0
    assert done.stdout == (
        f"mjcf-model {importlib.metadata.version('mjcf-model')} (MuJoCo {mujoco.__version__})\n"
    )


def test_prefix_and_scale_to_stdout(tmp_path: Path) -> None:
    """Prefix renames what the model declares; scale doubles lengths, as MuJoCo compiles."""
    arm = tmp_path / "arm.xml"
    arm.write_text(UNTIDY)
    prefixed = run("prefix", str(arm), "left_")
    assert prefixed.returncode == 0, prefixed.stderr
    renamed = mujoco.MjModel.from_xml_string(prefixed.stdout)
    assert renamed.joint("left_elbow").id == 0 and renamed.camera("left_front").id == 0
    scaled = tmp_path / "big.xml"
    assert run("scale", str(arm), "--factor", "2", "-o", str(scaled)).returncode == 0
    original = mujoco.MjModel.from_xml_path(str(arm))
    big = mujoco.MjModel.from_xml_path(str(scaled))
    assert np.allclose(big.geom_size, 2 * original.geom_size)
    assert np.allclose(big.site_pos, 2 * original.site_pos)
    assert run("scale", str(arm), "--factor", "1", "2").returncode == 2  # two factors


def test_export_verb(tmp_path: Path) -> None:
    """Export writes a movable folder holding the model and the files it uses."""
    assets = Path(__import__("robosuite").__file__).parent / "models" / "assets"
    done = run("export", str(assets / "objects" / "can.xml"), str(tmp_path / "folder"))
    assert done.returncode == 0, done.stderr
    written = tmp_path / "folder" / "can.xml"
    assert sorted(p.name for p in (tmp_path / "folder").iterdir()) == ["assets", "can.xml"]
    original = mujoco.MjModel.from_xml_path(str(assets / "objects" / "can.xml"))
    moved = mujoco.MjModel.from_xml_path(str(written))
    assert model_differences(original, moved, ignore=path_fields()) == []
    again = run("export", str(assets / "objects" / "can.xml"), str(tmp_path / "folder"))
    assert again.returncode == 2 and "empty" in again.stderr
