"""Renaming bodies whose names a skin reads from its ``.skn`` file.

A skin file names the bodies its bones bind to. MuJoCo is the referee: when a
renaming changes one of those bodies (a flexcomp's bodies, or attached bodies
through the attach prefix), the renamed text fails in MuJoCo with the skin's
bodies unknown, so the renaming must refuse; when it changes none, the result
compiles in MuJoCo.
"""

from __future__ import annotations

import re
from pathlib import Path

import mujoco
import pytest

from mjcf_model.bridge.compare import compile_text_beside, compiled_names, model_differences
from mjcf_model.errors import MjcfError, MjcfValueError
from mjcf_model.transforms.naming.renaming import prefixed, renamed
from serializers import dumps, loads
from tests.support.oracles import RENAMING_FIELDS
from tests.support.skin_files import skin_file

#: A flexcomp whose three bodies a file skin binds (no named body besides).
ROPE = """<mujoco><asset><skin name="hide" file="rope.skn"/></asset><worldbody>
  <geom name="floor" type="plane" size="1 1 0.1"/>
  <flexcomp name="rope" type="grid" dim="1" count="3 1 1" spacing="0.05 0.05 0.05"
            radius="0.01" mass="0.1"><edge equality="true"/></flexcomp>
</worldbody></mujoco>"""

#: An attached child whose bodies a file skin binds.
CHILD = """<mujoco model="kid"><worldbody>
  <body name="palm"><geom size="0.1"/><body name="x1" pos="0 0 0.3"><geom size="0.05"/></body>
  </body></worldbody></mujoco>"""
ATTACHED = """<mujoco><asset><model name="kid" file="child.xml"/><skin name="hide" file="hand.skn"/>
</asset><worldbody><geom name="floor" type="plane" size="1 1 0.1"/>
  <body name="mount" pos="0 0 1"><attach model="kid" body="palm" prefix="g_"/></body>
</worldbody></mujoco>"""


def refusal(file: str) -> str:
    """The whole message of the refusal to rename bodies a skin read from ``file`` binds."""
    return (
        f"cannot rename the bodies of a model where skin 'hide' is read from {file!r}: the file "
        "names the bodies its bones bind to, and MuJoCo would not find them; write the skin "
        "inline first with serializers.skins.inline_skin_files(model, model_folder)"
    )


@pytest.fixture
def rope(tmp_path: Path) -> Path:
    """The flexcomp model and its skin file, bound to rope_0, rope_1 and rope_2."""
    skin_file(tmp_path / "rope.skn", ("rope_0", "rope_1", "rope_2"))
    path = tmp_path / "rope.xml"
    path.write_text(ROPE, encoding="utf-8")
    return path


@pytest.fixture
def attached(tmp_path: Path) -> Path:
    """The attaching model, its child and its skin file, bound to g_palm, g_x1 and g_palm."""
    skin_file(tmp_path / "hand.skn", ("g_palm", "g_x1", "g_palm"))
    (tmp_path / "child.xml").write_text(CHILD, encoding="utf-8")
    path = tmp_path / "attached.xml"
    path.write_text(ATTACHED, encoding="utf-8")
    return path


def test_renaming_a_flexcomp_bound_by_a_file_skin_is_refused(rope: Path) -> None:
    """Renaming the flexcomp renames its bodies: MuJoCo would not find the skin's bones."""
    mujoco.MjModel.from_xml_path(str(rope))
    with pytest.raises(ValueError, match="unknown body 'rope_0' in skin"):
        compile_text_beside(ROPE.replace('name="rope"', 'name="cord"'), rope)
    with pytest.raises(MjcfValueError, match=f"^{re.escape(refusal('rope.skn'))}$") as info:
        renamed(loads(ROPE), {"flex": {"rope": "cord"}})
    assert isinstance(info.value, MjcfError)


def test_renaming_no_body_beside_a_file_skin_compiles(rope: Path, attached: Path) -> None:
    """Renaming only geoms changes no skin body: no refusal, and MuJoCo compiles the result."""
    for path, text in ((rope, ROPE), (attached, ATTACHED)):
        original = mujoco.MjModel.from_xml_path(str(path))
        for new in (
            renamed(loads(text), {"geom": {"floor": "ground"}}),
            prefixed(loads(text), "p_", namespaces={"geom"}),
        ):
            changed = compile_text_beside(dumps(new), path)
            assert model_differences(original, changed, ignore=RENAMING_FIELDS) == []
            assert compiled_names(changed)["body"] == compiled_names(original)["body"]


def test_prefixing_attach_prefixes_bound_by_a_file_skin_is_refused(attached: Path) -> None:
    """Prefixing the attach prefix renames attached bodies even when no declared body changes."""
    assert "g_x1" in compiled_names(mujoco.MjModel.from_xml_path(str(attached)))["body"]
    with pytest.raises(ValueError, match="unknown body 'g_palm' in skin"):
        compile_text_beside(ATTACHED.replace('prefix="g_"', 'prefix="p_g_"'), attached)
    with pytest.raises(MjcfValueError, match=f"^{re.escape(refusal('hand.skn'))}$"):
        prefixed(loads(ATTACHED), "p_", exclude={"mount", "floor", "kid", "hide"})
