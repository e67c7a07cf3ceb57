"""Tests of ``mjcf_model.tools.formatting``."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import mujoco
import numpy as np
import pytest
from hypothesis import given

from mjcf_model.bridge.compare import model_differences, path_fields
from mjcf_model.serializers import dumps
from mjcf_model.strategies import models
from mjcf_model.tools.formatting import (
    FormatOptions,
    format_file,
    format_text,
    options_from_pyproject,
)
from tests.conftest import compiling_corpus, corpus_id, loading_corpus

# -- ``fmt``'s library: every real file's canonical form is proven and stable. -----------------


COMPILING = set(compiling_corpus())


@pytest.mark.parametrize("path", loading_corpus(), ids=corpus_id)
def test_corpus_canonical_form_is_proven_and_stable(path: Path) -> None:
    """Each corpus file's rewrite is proven unchanged, and formatting it again does nothing.

    Proven: it compiles to the same model, or, for files MuJoCo rejects alone,
    reads to the same elements.
    """
    result = format_file(path)
    assert result.safe, result.differences
    proofs = ("compiled", "unchanged") if path in COMPILING else ("elements", "unchanged")
    assert result.proof in proofs
    again = format_text(result.text, filename=str(path))
    assert not again.changed and again.safe


def test_text_without_a_file_compiles_from_memory() -> None:
    """Text given alone is checked by compiling it; the canonical text is MuJoCo-equivalent."""
    result = format_text("<mujoco><worldbody><geom size='.5' type='sphere'/></worldbody></mujoco>")
    assert (result.proof, result.safe) == ("compiled", True)
    assert '<geom size=".5" type="sphere"/>' in result.text  # the number as written


def test_fragment_is_compared_element_by_element() -> None:
    """A part MuJoCo rejects on its own (its includer's material) is proven by its elements."""
    result = format_text("<mujoco><worldbody><geom  size='1' material='m'/></worldbody></mujoco>")
    assert result.proof == "elements" and result.safe and result.changed


# -- ``mjcf-model fmt`` as a formatter people keep on: layout changes, the author's choices
#    stay.
#
# Each rewrite is also proven by MuJoCo (the formatter's own proof: the compiled
# models are identical), and formatting the result again changes nothing.


#: An arm as people write it: a declaration and a licence comment before the root,
#: sections separated by blank lines, a wrapped start tag, numbers spelled their way,
#: a comment after an element on its line.
ARM = """<?xml version="1.0" encoding="utf-8"?>
<!-- Copyright: the arm's authors. -->


<mujoco model="arm">
  <compiler angle="radian"/>
  <option timestep="2e-3"
          integrator="implicitfast"/>



  <default>
    <default class="link">{LONG_GEOM}</default>
  </default>

  <worldbody>

    <body name="base" pos="0 0 0.10">
      <inertial pos="0 0 0.05" mass="1.25" diaginertia="8.2904e-7 8.2904e-07 1.0E-6"/>
      <joint name="shoulder" axis="0 0 1" range="-2.8973 2.8973" damping="0.10"/> <!-- the base -->
      <geom class="link" type="capsule" size="0.05" fromto="0 0 0   0 0 0.3"/>
    </body>
  </worldbody>
</mujoco>
""".replace(
    "{LONG_GEOM}",
    '<geom rgba=".8 .8 .8 1" contype="0" conaffinity="0" group="2" '
    'friction="1 5e-3 1e-4" solref="0.02 1"/>',
)


def _compiled(text: str) -> mujoco.MjModel:
    return mujoco.MjModel.from_xml_string(text)


def _same_model(a: str, b: str) -> None:
    assert model_differences(_compiled(a), _compiled(b), ignore=path_fields()) == []


def test_blank_lines_comments_and_numbers_stay_as_written() -> None:
    """One blank line where there were several; none after a start tag; every number kept."""
    result = format_text(ARM)
    text = result.text
    assert result.safe and result.proof == "compiled"
    assert text.startswith(
        '<?xml version="1.0" encoding="utf-8"?>\n<!-- Copyright: the arm\'s authors. -->\n\n'
        '<mujoco model="arm">\n  <compiler angle="radian"/>\n'
    )
    assert '  <option timestep="2e-3" integrator="implicitfast"/>\n\n  <default>\n' in text
    assert "\n\n\n" not in text
    assert "  <worldbody>\n    <body" in text  # the blank line after the start tag goes
    assert "    </body>\n  </worldbody>\n</mujoco>\n" in text
    assert 'diaginertia="8.2904e-7 8.2904e-07 1.0E-6"' in text
    assert 'pos="0 0 0.10"' in text and 'damping="0.10"/> <!-- the base -->\n' in text
    assert 'fromto="0 0 0 0 0 0.3"' in text  # white space inside a list: one space
    _same_model(ARM, text)
    assert not format_text(text).changed


def test_a_long_start_tag_is_wrapped_one_attribute_a_line() -> None:
    """Over the width (default 100): one attribute a line, indented a level deeper."""
    text = format_text(ARM).text
    wrapped = (
        '    <default class="link">\n'
        "      <geom\n"
        '        rgba=".8 .8 .8 1"\n'
        '        contype="0"\n'
        '        conaffinity="0"\n'
        '        group="2"\n'
        '        friction="1 5e-3 1e-4"\n'
        '        solref="0.02 1"/>\n'
        "    </default>\n"
    )
    assert wrapped in text
    assert all(len(line) <= 100 for line in text.splitlines())
    wide = format_text(ARM, options=FormatOptions(width=200)).text
    assert '<geom rgba=".8 .8 .8 1" contype="0" conaffinity="0" group="2" friction="1' in wide
    assert not format_text(wide, options=FormatOptions(width=200)).changed
    _same_model(ARM, wide)


def test_normalize_numbers_writes_the_shortest_form() -> None:
    """``normalize_numbers``: each number in the fewest characters that read back to it."""
    text = format_text(ARM, options=FormatOptions(normalize_numbers=True)).text
    assert 'diaginertia="8.2904e-7 8.2904e-7 1e-6"' in text
    assert 'pos="0 0 0.1"' in text and 'rgba="0.8 0.8 0.8 1"' in text
    _same_model(ARM, text)
    compiled = _compiled(text)
    assert np.array_equal(compiled.body_inertia[1], [8.2904e-7, 8.2904e-7, 1e-6])


def test_indentation_and_width_come_from_pyproject(tmp_path: Path) -> None:
    """``[tool.mjcf-model]`` in the nearest ``pyproject.toml`` sets width and indentation."""
    (tmp_path / "pyproject.toml").write_text("[tool.mjcf-model]\nwidth = 120\nindent = 4\n")
    (tmp_path / "robots").mkdir()
    arm = tmp_path / "robots" / "arm.xml"
    arm.write_text(ARM)
    options, found = options_from_pyproject(arm.parent)
    assert found == tmp_path / "pyproject.toml"
    assert (options.width, options.indent) == (120, 4)
    done = subprocess.run(
        [sys.executable, "-m", "mjcf_model", "fmt", str(arm)],
        capture_output=True,
        text=True,
        check=False,
    )
    assert done.returncode == 0, done.stderr
    text = arm.read_text()
    assert '\n    <compiler angle="radian"/>\n' in text
    assert '        <geom rgba=".8 .8 .8 1" contype="0"' in text  # 4 spaces, fits 120
    narrow = subprocess.run(
        [sys.executable, "-m", "mjcf_model", "fmt", "--width", "60", "--diff", str(arm)],
        capture_output=True,
        text=True,
        check=False,
    )
    assert narrow.returncode == 1 and "+            <geom\n" in narrow.stdout
    (tmp_path / "pyproject.toml").write_text("[tool.mjcf-model]\nwidht = 120\n")
    refused = subprocess.run(
        [sys.executable, "-m", "mjcf_model", "fmt", "--check", str(arm)],
        capture_output=True,
        text=True,
        check=False,
    )
    assert refused.returncode == 2
    assert "pyproject.toml" in refused.stderr and "widht = 120" in refused.stderr


@given(models())
def test_drawn_models_format_to_a_fixed_point(model: object) -> None:
    """Any model the strategies draw formats to text MuJoCo compiles the same, once and for all."""
    text = dumps(model)  # type: ignore[arg-type]
    once = format_text(text)
    assert once.safe, once.differences
    assert not format_text(once.text).changed
    narrow = format_text(text, options=FormatOptions(width=20, indent=0))
    assert (
        narrow.safe
        and not format_text(narrow.text, options=FormatOptions(width=20, indent=0)).changed
    )


def test_the_linters_table_beside_the_formatters_settings_is_left_to_the_linter(
    tmp_path: Path,
) -> None:
    """``[tool.mjcf-model.lint]`` is no formatter setting, and no error for the formatter."""
    (tmp_path / "pyproject.toml").write_text(
        '[tool.mjcf-model]\nwidth = 90\n[tool.mjcf-model.lint]\nignore = ["A"]\n'
    )
    options, found = options_from_pyproject(tmp_path)
    assert options.width == 90 and found == tmp_path / "pyproject.toml"
