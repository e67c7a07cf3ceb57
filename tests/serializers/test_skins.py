"""Tests of ``mjcf_model.serializers.skins``."""

from __future__ import annotations

import itertools
from pathlib import Path

import mujoco
import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from mjcf_model import prefixed
from mjcf_model.bridge.compare import model_differences
from mjcf_model.nodes.asset import Bone, Skin
from mjcf_model.serializers import dumps, load, loads
from mjcf_model.serializers.skins import float32_as_written, inline_skin_files, read_skin
from tests.support.skin_files import _skin_model, skin_file

# -- ``compiled`` lets MuJoCo read the files that exist on disk, and compiles what MuJoCo would.
#
# Each model is written into a folder with its mesh, texture, included and asset
# ``<model>`` files; MuJoCo loading the file (``MjModel.from_xml_path``) is the
# referee, and ``compiled(load(path))`` must give the same model (but for the file paths it records,
# ``path_fields``) while reading none
# of those files itself (they go to MuJoCo by absolute path, so its cache serves
# them). Files given in ``assets=`` and files that are not on disk still go through
# MuJoCo's asset dictionary.


#: Numbers MuJoCo reads as float32 on every release (3.9 refuses text that underflows it).
_SKIN_NUMBERS = st.floats(-10, 10).filter(lambda v: v == 0 or abs(v) > 1e-30)


@given(st.lists(_SKIN_NUMBERS, min_size=9, max_size=60))
def test_float32_as_written_is_what_mujoco_reads_from_the_text(values: list[float]) -> None:
    """MuJoCo rounds a skin's written numbers to float32 once; so does the skin file writer."""
    values = values[: len(values) - len(values) % 3]
    halfway = [(float(a) + float(b)) / 2 for a, b in itertools.pairwise(np.float32(values))]
    vertices = (values + halfway)[: 3 * ((len(values) + len(halfway)) // 3)]
    read = mujoco.MjModel.from_xml_string(_skin_model(vertices)).skin_vert.ravel()
    assert read.tobytes() == float32_as_written(vertices).tobytes()


# -- A skin read from a file carries its numbers' text: a write copies it, never formats it.


def test_a_read_skin_is_a_loaded_element_of_its_own_text(tmp_path: Path) -> None:
    """``read_skin`` gives the skin as read from text: equal values, and that text kept."""
    path = skin_file(tmp_path / "sheet.skn", ("a", "b", "c"))
    skin = read_skin(path)
    assert skin.layout is not None and skin.children[0].layout is not None
    assert skin.layout.where()[0] == str(path)  # its elements come from the skin file
    assert skin == Skin(
        vertex=np.float32([0, 0, 0, 0.1, 0, 0, 0, 0.1, 0]).astype(float),
        face=[0, 1, 2],
        children=[
            Bone(
                body=body,
                bindpos=[
                    float(np.float32(0.01 * index)),
                    float(np.float32(0.02)),
                    float(np.float32(0.03)),
                ],
                bindquat=[1, 0, 0, 0],
                vertid=[index],
                vertweight=[1],
            )
            for index, body in enumerate(("a", "b", "c"))
        ],
    )


def test_an_inlined_skin_keeps_its_own_attributes_and_writes_the_numbers_read(
    tmp_path: Path,
) -> None:
    """Inlined, the skin keeps its element's attributes; the numbers' text is the skin's own.

    Renaming the bodies then edits only the bones' ``body`` values, and MuJoCo compiles the
    written model as the renamed model written canonically.
    """
    skin_file(tmp_path / "sheet.skn", ("a", "b", "c"))
    text = (
        '<mujoco><asset><skin file="sheet.skn" rgba="1 0 0 1" inflate="0.01"/></asset>'
        '<worldbody><body name="a"><geom size="0.1"/><body name="b"><geom size="0.1"/>'
        '<body name="c"><geom size="0.1"/></body></body></body></worldbody></mujoco>'
    )
    (tmp_path / "sheet.xml").write_text(text)
    model = load(tmp_path / "sheet.xml")
    inline = inline_skin_files(model)
    (skin,) = inline.elements[0].elements
    assert isinstance(skin, Skin) and skin.file is None
    assert (skin.name, skin.rgba, skin.inflate) == ("sheet", (1.0, 0.0, 0.0, 1.0), 0.01)
    read = read_skin(tmp_path / "sheet.skn")
    assert skin.vertex is read.vertex and skin.children == read.children
    renamed = prefixed(model, "p_")
    written = dumps(renamed)
    assert read.children[0].layout is not None
    vertex_text = read.layout.whole().split('vertex="')[1].split('"')[0] if read.layout else ""
    assert f'vertex="{vertex_text}"' in written
    assert loads(written, base_dir=tmp_path) == renamed
    canonical = dumps(renamed, canonical=True)
    assert (
        model_differences(
            mujoco.MjModel.from_xml_string(written), mujoco.MjModel.from_xml_string(canonical)
        )
        == []
    )
