"""A model MuJoCo rejects raises MjcfCompileError naming the user's file, line and element.

MuJoCo is the referee: it compiles the same file itself, and its own line (for a
file it read directly) and its own words must be in the error.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import mujoco
import pytest

from mjcf_model import Body, Geom, Joint, Mujoco, Worldbody, attach, compiled, prefixed
from mjcf_model.errors import MjcfCompileError
from mjcf_model.serializers import dumps, load, loads
from mjcf_model.tree.traversal import with_children

#: A robot with a slot for one element MuJoCo rejects.
ROBOT = """<mujoco model="robot">
  <default>
    <default class="soft"><geom rgba="0 0 1 1"/></default>
  </default>
  <worldbody>
    <body name="base" pos="0 0 0.1">
      <geom name="plate" size="0.2 0.2 0.02" type="box"/>
      <body name="arm">
        <joint name="shoulder" type="hinge" axis="0 1 0"/>
        <geom name="upper" type="capsule" size="0.03" fromto="0 0 0 0 0 0.3"/>
        {bad}
      </body>
    </body>
  </worldbody>
</mujoco>
"""

#: Elements MuJoCo rejects, and the element path each stands at in ROBOT.
BAD = {
    "unknown class": (
        '<geom name="tip" class="missing" size="0.02"/>',
        "/mujoco/worldbody/body[@name='base']/body[@name='arm']/geom[@name='tip']",
    ),
    "unknown mesh": (
        '<geom type="mesh" mesh="nowhere"/>',
        "/mujoco/worldbody/body[@name='base']/body[@name='arm']/geom[2]",
    ),
    "reversed range": (
        '<joint name="wrist" type="hinge" range="1 -1" limited="true"/>',
        "/mujoco/worldbody/body[@name='base']/body[@name='arm']/joint[@name='wrist']",
    ),
}


def line_of(text: str, fragment: str) -> int:
    """The 1-based line of ``text`` that holds ``fragment``."""
    (line,) = [n for n, row in enumerate(text.splitlines(), start=1) if fragment in row]
    return line


def mujoco_says(path: Path) -> tuple[str, int]:
    """What MuJoCo says compiling the file itself (its words), and the line it names."""
    with pytest.raises(ValueError) as caught:
        mujoco.MjModel.from_xml_path(str(path))
    message = str(caught.value).strip()
    found = re.search(r", line (\d+)$", message)
    assert found is not None, message
    return message.split("\nElement")[0], int(found.group(1))


def rejection(model: Mujoco) -> MjcfCompileError:
    """The error compiling ``model`` raises."""
    with pytest.raises(MjcfCompileError) as caught:
        compiled(model)
    return caught.value


@pytest.mark.parametrize("case", sorted(BAD))
def test_rejected_file_names_file_line_and_path(tmp_path: Path, case: str) -> None:
    """The error names the file, MuJoCo's own line in it, the path and MuJoCo's words."""
    bad, path = BAD[case]
    text = ROBOT.format(bad=bad)
    robot = tmp_path / "robot.xml"
    robot.write_text(text)
    words, line = mujoco_says(robot)
    assert line == line_of(text, bad)
    error = rejection(load(robot))
    assert (error.file, error.line, error.path) == (str(robot), line, path)
    assert str(error) == f"{robot}:{line}: {path}: MuJoCo rejects the model: {words}"


def test_element_added_before_keeps_its_line(tmp_path: Path) -> None:
    """Elements added in code shift the written text's lines, not the file's."""
    bad, path = BAD["reversed range"]
    text = ROBOT.format(bad=bad)
    robot = tmp_path / "robot.xml"
    robot.write_text(text)
    model = load(robot)
    assert model.worldbody is not None
    added = [Body(name=f"extra{i}", children=[Geom(size=[0.1])]) for i in range(5)]
    worldbody = with_children(model.worldbody, [*added, *model.worldbody.children])
    model = with_children(model, [worldbody if c is model.worldbody else c for c in model.children])
    assert line_of(dumps(model), bad) > line_of(text, bad)  # MuJoCo's line is another
    error = rejection(model)
    assert (error.file, error.line, error.path) == (str(robot), line_of(text, bad), path)
    assert mujoco_says(robot)[0] in error.detail


def test_included_file_names_its_own_line(tmp_path: Path) -> None:
    """An element of an included file names that file and its line there (MuJoCo says 0)."""
    bad, _ = BAD["unknown class"]
    part = (
        f'<mujoco>\n  <body name="hand">\n    <geom size="0.1"/>\n    {bad}\n  </body>\n</mujoco>\n'
    )
    (tmp_path / "parts").mkdir()
    (tmp_path / "parts" / "hand.xml").write_text(part)
    main = tmp_path / "main.xml"
    main.write_text(
        '<mujoco>\n  <worldbody>\n    <include file="parts/hand.xml"/>\n  </worldbody>\n</mujoco>\n'
    )
    words, mujoco_line = mujoco_says(main)
    assert mujoco_line == 0  # MuJoCo itself cannot say where
    for inline in (False, True):
        error = rejection(load(main, inline_includes=inline))
        assert error.file is not None
        assert Path(error.file).resolve() == (tmp_path / "parts" / "hand.xml").resolve()
        assert error.line == line_of(part, bad)
        assert error.path == "/mujoco/worldbody/body[@name='hand']/geom[@name='tip']"
        assert words in error.detail


def test_element_after_an_include_names_the_main_file(tmp_path: Path) -> None:
    """With includes kept, an element of the main file names the main file's line."""
    (tmp_path / "floor.xml").write_text(
        '<mujoco>\n<geom name="floor" type="plane" size="1 1 1"/>\n<geom size="1"/>\n</mujoco>\n'
    )
    bad, _ = BAD["reversed range"]
    text = ROBOT.format(bad=bad).replace(
        "<worldbody>", '<worldbody>\n    <include file="floor.xml"/>'
    )
    main = tmp_path / "main.xml"
    main.write_text(text)
    words, line = mujoco_says(main)
    error = rejection(load(main))
    assert (error.file, error.line) == (str(main), line)
    assert line == line_of(text, bad)
    assert words in error.detail


def test_attached_part_names_the_parts_file(tmp_path: Path) -> None:
    """A part attached with a prefix from another folder names its own file and line."""
    bad, _ = BAD["reversed range"]
    text = ROBOT.format(bad=bad)
    (tmp_path / "robots").mkdir()
    (tmp_path / "scenes").mkdir()
    robot = tmp_path / "robots" / "robot.xml"
    robot.write_text(text)
    scene = tmp_path / "scenes" / "scene.xml"
    scene.write_text(
        '<mujoco model="scene">\n  <worldbody>\n    <light pos="0 0 3"/>\n'
        '    <geom name="floor" type="plane" size="2 2 0.1"/>\n'
        '    <body name="table"><geom size="0.5 0.5 0.02" type="box"/></body>\n'
        "  </worldbody>\n</mujoco>\n"
    )
    words, line = mujoco_says(robot)
    error = rejection(attach(load(scene), load(robot), prefix="left/"))
    assert (error.file, error.line) == (str(robot), line)
    assert error.path == (
        "/mujoco/worldbody/body[@name='left/base']/body[@name='left/arm']/joint[@name='left/wrist']"
    )
    assert words in error.detail
    renamed = rejection(prefixed(load(robot), "r_"))
    assert (renamed.file, renamed.line) == (str(robot), line)


def test_several_elements_on_one_line(tmp_path: Path) -> None:
    """On a line holding several elements, the one MuJoCo rejects is named."""
    text = (
        '<mujoco><worldbody><body name="a"><geom size="1"/><geom class="x" size="1"/>'
        '<geom size="2"/></body></worldbody></mujoco>'
    )
    path = tmp_path / "flat.xml"
    path.write_text(text)
    words, line = mujoco_says(path)
    error = rejection(load(path))
    assert (error.file, error.line) == (str(path), line)
    assert error.path == "/mujoco/worldbody/body[@name='a']/geom[2]"
    assert words in error.detail


def test_model_built_in_code_names_the_path() -> None:
    """A model built in code has no file: the element path is named."""
    joint = Joint(name="j", type="hinge", range=(2, 1), limited="true")
    model = Mujoco(
        children=[Worldbody(children=[Body(name="b", children=[joint, Geom(size=[1])])])]
    )
    error = rejection(model)
    assert (error.file, error.line) == (None, None)
    assert error.path == "/mujoco/worldbody/body[@name='b']/joint[@name='j']"
    assert str(error).startswith(f"{error.path}: MuJoCo rejects the model: Error: range")


def test_message_without_a_line_says_so(tmp_path: Path) -> None:
    """MuJoCo names no line for a wrong keyframe size: the error says so and keeps its words."""
    text = (
        '<mujoco>\n  <worldbody>\n    <body><joint type="hinge"/><geom size="1"/></body>\n'
        '  </worldbody>\n  <keyframe><key qpos="1 2"/></keyframe>\n</mujoco>\n'
    )
    path = tmp_path / "keys.xml"
    path.write_text(text)
    with pytest.raises(ValueError) as caught:
        mujoco.MjModel.from_xml_path(str(path))
    words = str(caught.value).strip().split("\nElement")[0]
    error = rejection(loads(text, filename=str(path)))
    assert (error.file, error.line, error.path) == (str(path), None, None)
    assert "names no line" in error.detail and words in error.detail


def run(*arguments: str) -> subprocess.CompletedProcess[str]:
    """``mjcf-model ARGUMENTS`` in a fresh process, as a user runs it."""
    return subprocess.run(
        [sys.executable, "-m", "mjcf_model", *arguments],
        capture_output=True,
        text=True,
        check=False,
        env={k: v for k, v in os.environ.items() if k != "MUJOCO_GL"},
    )


def test_cli_verbs_print_the_location(tmp_path: Path) -> None:
    """check, compose, render and info print file:line: element path: MuJoCo's words."""
    bad, path = BAD["reversed range"]
    text = ROBOT.format(bad=bad)
    (tmp_path / "robots").mkdir()
    robot = tmp_path / "robots" / "robot.xml"
    robot.write_text(text)
    scene = tmp_path / "scene.xml"
    scene.write_text('<mujoco>\n<worldbody>\n<light pos="0 0 3"/>\n</worldbody>\n</mujoco>\n')
    words, line = mujoco_says(robot)
    where = f"{robot}:{line}: "
    checked = run("check", str(robot))
    assert f"{where}{path}: MuJoCo rejects the model: {words}\n" in checked.stdout
    out = tmp_path / "out.xml"
    composed = run("compose", str(out), str(scene), f"{robot}:left/")
    assert composed.returncode == 2 and not out.exists()
    assert composed.stderr.startswith(f"mjcf-model compose: {where}/mujoco/worldbody/")
    assert f"joint[@name='left/wrist']: MuJoCo rejects the model: {words}" in composed.stderr
    rendered = run("render", str(robot), "-o", str(tmp_path / "robot.png"))
    assert rendered.returncode == 2
    assert (
        rendered.stderr == f"mjcf-model render: {where}{path}: MuJoCo rejects the model: {words}\n"
    )
    informed = run("info", str(robot))
    assert informed.returncode == 0, informed.stderr
    assert informed.stdout.endswith(
        f"compiles: no: {where}{path}: MuJoCo rejects the model: {words}\n"
    )
    assert run("info", str(scene)).stdout.endswith("compiles: yes\n")
