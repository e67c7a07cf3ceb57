"""Tests of ``mjcf_model.serializers.tidy``: a loaded file's layout made regular, nothing else."""

from __future__ import annotations

import mujoco

from mjcf_model.bridge.compare import model_differences
from mjcf_model.serializers import loads
from mjcf_model.serializers.tidy import tidy_text

#: An untidy file: uneven indentation, a comment, a number spelled its own way.
UNTIDY = """<!-- before -->
<mujoco model="m">
      <option   timestep="2e-3"/>
  <worldbody>
 <body name="b"   pos="0 0 1"><!-- inside --><geom size=".1"/>
            <site name="s"/></body>
  </worldbody>
</mujoco>
"""


def test_the_tidy_form_is_regular_and_compiles_to_the_same_model() -> None:
    """Two spaces a level, one element a line, comments and spellings kept; MuJoCo agrees."""
    tidy = tidy_text(loads(UNTIDY))
    assert tidy == (
        "<!-- before -->\n"
        '<mujoco model="m">\n'
        '  <option timestep="2e-3"/>\n'
        "  <worldbody>\n"
        '    <body name="b" pos="0 0 1">\n'
        "      <!-- inside -->\n"
        '      <geom size=".1"/>\n'
        '      <site name="s"/>\n'
        "    </body>\n"
        "  </worldbody>\n"
        "</mujoco>\n"
    )
    original, tidied = (mujoco.MjModel.from_xml_string(t) for t in (UNTIDY, tidy))
    assert model_differences(original, tidied) == []
    assert tidy_text(loads(tidy)) == tidy


def test_options_wrap_long_tags_indent_and_normalize_numbers() -> None:
    """A tag longer than the width takes one attribute a line; numbers may be made shortest."""
    model = loads('<mujoco><option timestep="2e-3" gravity="0 0 -9.810"/></mujoco>')
    assert tidy_text(model, width=30, indent="\t", normalize_numbers=True) == (
        '<mujoco>\n\t<option\n\t\ttimestep="0.002"\n\t\tgravity="0 0 -9.81"/>\n</mujoco>\n'
    )
