"""The verbs of ``mjcf-model`` run as a user runs them: a process, real files, exit codes."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import mujoco
import numpy as np
import pytest

from mjcf_model.bridge.compare import model_differences, path_fields
from mjcf_model.tools.cli import main
from tests.support.cli import UNTIDY, run

VERBS = (
    "check",
    "fmt",
    "diff",
    "compose",
    "prefix",
    "scale",
    "export",
    "info",
    "render",
    "examples",
)


@pytest.mark.parametrize("verb", VERBS)
def test_every_verb_has_help(verb: str) -> None:
    """``mjcf-model VERB --help`` describes the verb and exits 0."""
    done = run(verb, "--help")
    assert done.returncode == 0, done.stderr
    assert done.stdout.startswith(f"usage: mjcf-model {verb}")


def test_fmt_check_write_then_clean(tmp_path: Path) -> None:
    """--check fails on an untidy file, fmt rewrites it, then --check passes: ruff's contract."""
    path = tmp_path / "arm.xml"
    path.write_text(UNTIDY)
    before = mujoco.MjModel.from_xml_path(str(path))
    checked = run("fmt", "--check", str(path))
    assert checked.returncode == 1 and f"would reformat {path}" in checked.stderr
    assert path.read_text() == UNTIDY
    written = run("fmt", str(path))
    assert written.returncode == 0, written.stderr
    assert "1 file reformatted, 0 files unchanged" in written.stderr
    assert path.read_text() != UNTIDY and "  <worldbody>\n" in path.read_text()
    after = mujoco.MjModel.from_xml_path(str(path))
    assert model_differences(before, after, ignore=path_fields()) == []
    assert run("fmt", "--check", str(path)).returncode == 0
    assert list(tmp_path.iterdir()) == [path]  # no temporary file left behind


def test_fmt_diff_and_stdin(tmp_path: Path) -> None:
    """--diff prints a unified diff and writes nothing; - reads stdin and writes stdout."""
    path = tmp_path / "arm.xml"
    path.write_text(UNTIDY)
    shown = run("fmt", "--diff", str(path))
    assert shown.returncode == 1
    assert shown.stdout.startswith(f"--- {path}\n+++ {path}\n@@")
    assert '+      <geom name="upper" size="0.10 0.2" type="capsule"/>' in shown.stdout
    assert path.read_text() == UNTIDY
    piped = run("fmt", "-", stdin=UNTIDY)
    assert piped.returncode == 0, piped.stderr
    assert piped.stdout.startswith('<mujoco model="arm">\n  <default>\n')
    assert run("fmt", "-", stdin=piped.stdout).stdout == piped.stdout


def test_fmt_refuses_a_rewrite_that_compiles_differently(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    """When the proof fails the file is left as it was and the exit status is 2."""
    import mjcf_model.tools.formatting as formatting

    path = tmp_path / "arm.xml"
    path.write_text(UNTIDY)
    monkeypatch.setattr(formatting, "written_differences", lambda *args: ("geom_size",))
    assert main(["fmt", str(path)]) == 2
    assert "not rewritten, it changes the model: geom_size" in capsys.readouterr().err
    assert path.read_text() == UNTIDY


def test_fmt_keeps_the_file_when_the_write_fails(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    """A write that fails half way leaves the old file whole and no temporary file."""
    path = tmp_path / "arm.xml"
    path.write_text(UNTIDY)

    def broken(source: object, target: object) -> None:
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(os, "replace", broken)
    assert main(["fmt", "--quiet", str(path)]) == 2
    assert "cannot write: No space left on device" in capsys.readouterr().err
    assert path.read_text() == UNTIDY
    assert list(tmp_path.iterdir()) == [path]


def test_bad_file_names_file_and_line(tmp_path: Path) -> None:
    """A malformed file fails every reading verb with the file and line, exit status 2."""
    bad = tmp_path / "bad.xml"
    bad.write_text("<mujoco>\n<worldbody>\n<geom size='1'>\n</worldbody></mujoco>")
    for arguments in (["fmt", str(bad)], ["info", str(bad)], ["diff", str(bad), str(bad)]):
        done = run(*arguments)
        assert done.returncode == 2, arguments
        assert f"{bad}:4" in done.stderr, done.stderr


def test_diff_exit_codes_and_json(tmp_path: Path) -> None:
    """0 when only formatting differs, 1 with the change listed, 2 for a missing file."""
    first, second, third = tmp_path / "a.xml", tmp_path / "b.xml", tmp_path / "c.xml"
    first.write_text(UNTIDY)
    second.write_text(run("fmt", "-", stdin=UNTIDY).stdout)
    third.write_text(UNTIDY.replace('pos="0 0 .3"', 'pos="0 0 .4"'))
    assert run("diff", str(first), str(second)).returncode == 0
    different = run("diff", str(first), str(third))
    assert different.returncode == 1
    assert different.stdout == (
        "~ /mujoco/worldbody/body[@name='arm']/site[@name='tip'] pos: 0 0 0.3 -> 0 0 0.4\n"
    )
    report = json.loads(run("diff", "--json", "--compiled", str(first), str(third)).stdout)
    assert report["equal"] is False
    assert report["changes"][0]["attribute"] == "pos"
    assert "site_pos" in report["compiled"]
    assert run("diff", str(first), str(tmp_path / "missing.xml")).returncode == 2


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


def test_an_output_into_a_missing_folder(tmp_path: Path) -> None:
    """A verb's output path creates its missing folders; a file in the way exits 2, named."""
    arm = tmp_path / "arm.xml"
    arm.write_text(UNTIDY)
    scaled = tmp_path / "out" / "nested" / "big.xml"
    done = run("scale", str(arm), "--factor", "2", "-o", str(scaled))
    assert done.returncode == 0, done.stderr
    original = mujoco.MjModel.from_xml_path(str(arm))
    assert np.allclose(mujoco.MjModel.from_xml_path(str(scaled)).geom_size, 2 * original.geom_size)
    blocked = run("scale", str(arm), "--factor", "2", "-o", str(arm / "big.xml"))
    assert blocked.returncode == 2
    assert f"{str(arm)!r} is a file, not a folder" in blocked.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["arm.xml", "out"]


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


def test_info_summary_and_element(tmp_path: Path) -> None:
    """Info lists counts, names, classes; --element names the class that gives each value."""
    arm = tmp_path / "arm.xml"
    arm.write_text(UNTIDY)
    summary = run("info", str(arm), "--defaults")
    assert summary.returncode == 0, summary.stderr
    assert "model: arm\n" in summary.stdout
    assert "  body (1): arm\n" in summary.stdout
    assert "    red: sets geom\n" in summary.stdout
    element = run("info", str(arm), "--element", "geom:upper")
    assert element.stdout.splitlines()[-1] == "rgba = 1 0 0 1 (class red)"
    assert run("info", str(arm), "--element", "upper").returncode == 2
    assert run("info", "-", stdin=UNTIDY).stdout == run("info", str(arm)).stdout


def test_readme_main_job(tmp_path: Path) -> None:
    """The README's main job: two bundled arms on the workcell, each where it belongs.

    The arm (radians) is attached twice to the workcell (degrees, its own mesh
    folder) at its two mount sites, and the scene compiles.
    """
    demo = tmp_path / "demo"
    assert run("examples", str(demo)).returncode == 0
    scene = demo / "scene.xml"
    parts = [f"{demo / 'arm.xml'}:left_@left_mount", f"{demo / 'arm.xml'}:right_@right_mount"]
    done = run("compose", str(scene), str(demo / "workcell" / "workcell.xml"), *parts)
    assert done.returncode == 0, done.stderr
    compiled = mujoco.MjModel.from_xml_path(str(scene))
    data = mujoco.MjData(compiled)
    mujoco.mj_kinematics(compiled, data)
    assert np.allclose(data.site("left_tip").xpos, [-0.2, 0, 1])
    assert np.allclose(data.site("right_tip").xpos, [0.2, 0, 1])
    assert np.allclose(compiled.joint("right_elbow").range, [-2, 2])  # radians, as the arm says
    assert compiled.mesh("wedge").id == 0
    summary = run("info", str(scene))
    assert "  site (4): left_mount, right_mount, left_tip, right_tip\n" in summary.stdout
    assert run("examples", str(demo)).returncode == 2  # not empty: nothing overwritten


def test_readme_main_job_command_runs_as_written(tmp_path: Path) -> None:
    """The README's main-job command (from the installed package's description) runs here."""
    from importlib import metadata

    readme = metadata.metadata("mjcf-model").get_payload()
    assert isinstance(readme, str)
    setup = "python3 -m venv .venv && .venv/bin/pip install -e . && "
    [line] = [line for line in readme.splitlines() if line.startswith(setup)]
    command = line.removeprefix(setup).replace(
        ".venv/bin/mjcf-model", f"{sys.executable} -m mjcf_model"
    )
    env = {k: v for k, v in os.environ.items() if k != "MUJOCO_GL"}
    done = subprocess.run(
        ["bash", "-c", command], cwd=tmp_path, capture_output=True, text=True, check=False, env=env
    )
    assert done.returncode == 0, done.stderr
    assert done.stdout.startswith("model: workcell\n")
    assert (tmp_path / "demo" / "scene.png").read_bytes().startswith(b"\x89PNG")


def test_check_reads_stdin() -> None:
    """``check -`` round-trips the text piped in; MuJoCo's rejection is reported, not a crash."""
    done = run("check", "-", stdin=UNTIDY)
    assert done.returncode == 0 and done.stdout.startswith("identical     <stdin>\n")
    rejected = run("check", "-", stdin="<mujoco><worldbody><geom/></worldbody></mujoco>")
    assert rejected.returncode == 1 and rejected.stdout.startswith("not compiled  <stdin>")


def test_outputs_resolve_from_where_they_are_written(tmp_path: Path) -> None:
    """Outputs resolve from where they are written, and compose writes all or nothing.

    A model printed to stdout names its meshes from the working folder; new files get
    the umask's mode; compose checks the export folder before writing anything.
    """
    demo = tmp_path / "demo"
    assert run("examples", str(demo)).returncode == 0
    printed = subprocess.run(
        [
            sys.executable,
            "-m",
            "mjcf_model",
            "prefix",
            str(demo / "workcell" / "workcell.xml"),
            "p_",
        ],
        capture_output=True,
        text=True,
        check=False,
        cwd=tmp_path,
    )
    assert printed.returncode == 0, printed.stderr
    (tmp_path / "printed.xml").write_text(printed.stdout)
    assert mujoco.MjModel.from_xml_path(str(tmp_path / "printed.xml")).mesh("p_wedge").id == 0
    scene = tmp_path / "scene.xml"
    (tmp_path / "full").mkdir()
    (tmp_path / "full" / "x").write_text("")
    refused = run(
        "compose",
        str(scene),
        str(demo / "workcell" / "workcell.xml"),
        str(demo / "arm.xml"),
        "--export",
        str(tmp_path / "full"),
    )
    assert refused.returncode == 2 and not scene.exists()
    assert (
        run(
            "compose",
            str(scene),
            str(demo / "workcell" / "workcell.xml"),
            f"{demo / 'arm.xml'}:left/@left_mount",
        ).returncode
        == 0
    )
    assert mujoco.MjModel.from_xml_path(str(scene)).joint("left/elbow").id >= 0
    mask = os.umask(0)
    os.umask(mask)
    assert scene.stat().st_mode & 0o777 == 0o666 & ~mask
