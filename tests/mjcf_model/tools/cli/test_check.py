"""Tests of ``mjcf_model.tools.cli.check``."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import mujoco
import pytest

from mjcf_model.tools.check import CheckResult
from mjcf_model.tools.cli import example_path, main
from tests.support.cli import UNTIDY, run

# -- The ``mjcf-model`` command line. ----------------------------------------------------------


def test_example_is_identical(capsys: pytest.CaptureFixture[str]) -> None:
    """The bundled example round-trips; the report says so and the exit status is 0."""
    assert main(["check", "--example"]) == 0
    out = capsys.readouterr().out
    assert f"identical     {example_path()}" in out
    assert "1 file: 1 identical" in out


def test_errors_and_rejections(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """A file MuJoCo rejects fails the run (``--strict`` is still taken); so do missing files."""
    rejected = tmp_path / "rejected.xml"
    rejected.write_text("<mujoco><worldbody><geom type='box'/></worldbody></mujoco>")
    assert main(["check", str(rejected)]) == 1
    assert main(["check", "--strict", str(rejected)]) == 1
    assert main(["check", str(tmp_path / "missing.xml")]) == 1
    out = capsys.readouterr().out
    assert f"not compiled  {rejected}" in out
    assert "ERROR" in out and "no such file" in out


def test_every_failure_names_the_users_file_and_says_what_to_do(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """A missing mesh, a PNG, text without XML, an empty file, a folder: each names the file.

    And the line and element where there is one, and says what to do, in command-line
    words; MuJoCo's bare messages ("Error opening file", "XML parse error 8") do not show.
    """
    missing = tmp_path / "arm.xml"
    missing.write_text(
        '<mujoco>\n  <asset>\n    <mesh name="hand" file="nope/hand.stl"/>\n  </asset>\n'
        '  <worldbody><geom type="mesh" mesh="hand"/></worldbody>\n</mujoco>\n'
    )
    picture = tmp_path / "picture.png"
    picture.write_bytes(b"\x89PNG\r\n\x1a\n\x00\x00\x00\rIHDR")
    prose = tmp_path / "notes.xml"
    prose.write_text("hello, not a model\n")
    empty = tmp_path / "empty.xml"
    empty.write_bytes(b"")
    for path in (missing, picture, prose, empty, tmp_path):
        assert main(["check", str(path)]) == 1
    out = capsys.readouterr().out
    assert f"{missing}:3: /mujoco/asset/mesh[@name='hand']: <mesh file='nope/hand.stl'>" in out
    assert "put the file where the model names it" in out and "assets=" not in out
    assert f"{picture}: not an MJCF model: a PNG image, not XML" in out
    assert f'{prose}: not an MJCF model: a file without any XML element (it begins with "h' in out
    assert f"{empty}: not an MJCF model: a file without any XML element (it is empty)" in out
    assert f"a folder, not a file; name a model file in it: {tmp_path / 'arm.xml'}" in out
    assert "iconv" not in out and "Error opening file" not in out and "parse error" not in out


def test_a_difference_fails_the_run(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    """When the compiled models differ the fields are listed and the exit status is 1."""
    import mjcf_model.tools.cli.check as cli

    def differing(path: str, **_: object) -> CheckResult:
        return CheckResult(path=str(path), status="different", differences=("geom_size",))

    monkeypatch.setattr(cli, "check_file", differing)
    assert main(["check", "--example"]) == 1
    assert "fields: geom_size" in capsys.readouterr().out


def test_no_files_is_a_usage_error(capsys: pytest.CaptureFixture[str]) -> None:
    """Without files or --example the command says what to do."""
    assert main(["check"]) == 2
    assert "--example" in capsys.readouterr().err


# -- ``mjcf-model check`` as a CI job runs it: rejected models fail, parts are checked as parts.
#
# Every test runs the command in a fresh process on files written here, and the
# expected verdicts are MuJoCo's own (``MjModel.from_xml_path`` of each file).


#: A main model that declares a material and includes an arm that uses it.
_SCENE = """<mujoco model="scene">
  <asset>
    <material name="red" rgba="1 0 0 1"/>
  </asset>
  <include file="parts/arm.xml"/>
</mujoco>
"""
#: The arm: MuJoCo rejects it alone (the material is the scene's).
_ARM = """<mujoco>
  <worldbody>
    <body name="arm">
      <geom material="red" name="upper" size="0.05"/>
    </body>
  </worldbody>
</mujoco>
"""


def _check(*arguments: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "mjcf_model", "check", *arguments],
        capture_output=True,
        text=True,
        check=False,
    )


def _scene(folder: Path, scene: str = _SCENE) -> tuple[Path, Path]:
    (folder / "parts").mkdir()
    arm = folder / "parts" / "arm.xml"
    arm.write_text(_ARM)
    main = folder / "scene.xml"
    main.write_text(scene)
    return main, arm


def _rejects(path: Path) -> bool:
    try:
        mujoco.MjModel.from_xml_path(str(path))
    except ValueError:
        return True
    return False


def test_a_model_mujoco_rejects_fails_naming_file_line_and_element(tmp_path: Path) -> None:
    """Exit 1 by default (a CI job wired to ``check`` catches a broken model)."""
    broken = tmp_path / "broken.xml"
    broken.write_text(
        "<mujoco>\n  <worldbody>\n    <geom name='g' type='box'/>\n  </worldbody>\n</mujoco>\n"
    )
    assert _rejects(broken)
    done = _check(str(broken))
    assert done.returncode == 1
    assert f"not compiled  {broken}" in done.stdout
    assert f"{broken}:3: /mujoco/worldbody/geom[@name='g']" in done.stdout
    assert _check("--strict", str(broken)).returncode == 1  # old CI jobs keep working
    assert _check("--quiet", str(broken)).returncode == 1


def test_an_included_part_is_recognised_and_checked_with_its_scene(tmp_path: Path) -> None:
    """The arm alone is rejected by MuJoCo, but the scene including it compiles: a part."""
    main, arm = _scene(tmp_path)
    assert _rejects(arm) and not _rejects(main)
    done = _check(str(arm), str(main))
    assert done.returncode == 0, done.stdout
    assert (
        f"part          {arm}\n              a part for <include>, included by {main}"
        in done.stdout
    )
    assert "2 files: 1 identical, 1 part" in done.stdout


def test_a_part_whose_scene_is_rejected_fails(tmp_path: Path) -> None:
    """A part is only as good as the files including it: a broken scene fails the part."""
    main, arm = _scene(tmp_path, _SCENE.replace('name="red"', 'name="blue"'))
    assert _rejects(arm) and _rejects(main)
    done = _check(str(arm))
    assert done.returncode == 1
    assert f"not compiled  {arm}" in done.stdout and f"included by {main}" in done.stdout


def test_part_option_checks_a_part_without_its_scene(tmp_path: Path) -> None:
    """``--part``: a part with no scene in reach reads back the same, and says so."""
    (tmp_path / "alone").mkdir()
    arm = tmp_path / "alone" / "arm.xml"
    arm.write_text(_ARM)
    assert _check(str(arm)).returncode == 1  # not recognised: MuJoCo's verdict stands
    done = _check("--part", str(arm))
    assert done.returncode == 0, done.stdout
    assert "no file including it was found" in done.stdout


@pytest.mark.parametrize("bad", ["<mujoco><worldbody><geom pos='0 0'/></worldbody></mujoco>"])
def test_a_part_that_does_not_read_back_fails(tmp_path: Path, bad: str) -> None:
    """A part mjcf-model cannot read as MJCF fails, as any file does."""
    part = tmp_path / "part.xml"
    part.write_text(bad.replace("<mujoco>", "<mujoco").replace("</mujoco>", ""))
    assert _check("--part", str(part)).returncode == 1


def test_a_latin1_file_checks_identical_with_a_warning_and_formats_byte_for_byte(
    tmp_path: Path,
) -> None:
    """MuJoCo compiles a Latin-1 comment and name: ``check`` proves the round trip and warns.

    From a file and from standard input; ``fmt`` rewrites the layout and keeps the bytes.
    """
    data = (
        b'<mujoco model="caf\xe9">\n  <!-- caf\xe9 -->\n'
        b'<worldbody><geom size="1"/></worldbody>\n</mujoco>\n'
    )
    path = tmp_path / "old.xml"
    path.write_bytes(data)
    from_file = subprocess.run(
        [sys.executable, "-m", "mjcf_model", "check", str(path)], capture_output=True, check=False
    )
    from_stdin = subprocess.run(
        [sys.executable, "-m", "mjcf_model", "check", "-"],
        input=data,
        capture_output=True,
        check=False,
    )
    for done, name in ((from_file, str(path)), (from_stdin, "<stdin>")):
        assert done.returncode == 0, done.stdout
        out = done.stdout.decode()
        assert f"identical     {name}" in out
        assert "warning: line 1: 2 bytes that are not UTF-8 (0xE9 0xE9)" in out
        assert "iconv -f latin1 -t utf-8" in out
    formatted = subprocess.run(
        [sys.executable, "-m", "mjcf_model", "fmt", str(path)], capture_output=True, check=False
    )
    assert formatted.returncode == 0, formatted.stderr
    assert path.read_bytes() == data.replace(b"<worldbody>", b"  <worldbody>").replace(
        b"<geom", b"\n    <geom"
    ).replace(b"/></worldbody>", b"/>\n  </worldbody>")


# -- The verbs of ``mjcf-model`` run as a user runs them: a process, real files, exit codes. ---


def test_check_reads_stdin() -> None:
    """``check -`` round-trips the text piped in; MuJoCo's rejection is reported, not a crash."""
    done = run("check", "-", stdin=UNTIDY)
    assert done.returncode == 0 and done.stdout.startswith("identical     <stdin>\n")
    rejected = run("check", "-", stdin="<mujoco><worldbody><geom/></worldbody></mujoco>")
    assert rejected.returncode == 1 and rejected.stdout.startswith("not compiled  <stdin>")
