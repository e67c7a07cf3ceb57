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
from mjcf_model.serializers.skins import (
    float32_as_written,
    inline_skin_files,
    read_skin,
    skin_file_bytes,
)
from mjcf_model.values import format_value
from tests.support.skin_files import _skin_model

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


# -- A skin read from a file: its numbers are formatted once, and written from that text.


def _big_skin_file(path: Path, count: int) -> Path:
    """A skin file of ``count`` vertices on a line, each bound to one of three bodies."""
    rng = np.random.default_rng(0)
    vertex = np.float32(rng.uniform(-1, 1, 3 * count)).astype(float)
    bones = [
        Bone(
            body=body,
            bindpos=[0, 0, 0],
            bindquat=[1, 0, 0, 0],
            vertid=list(range(index, count, 3)),
            vertweight=[1.0] * len(range(index, count, 3)),
        )
        for index, body in enumerate(("a", "b", "c"))
    ]
    face = [i for v in range(count - 2) for i in (v, v + 1, v + 2)]
    data = skin_file_bytes(Skin(vertex=vertex, face=face, children=bones))
    assert data is not None
    path.write_bytes(data)
    return path


def test_a_read_skin_remembers_the_text_of_its_long_number_lists(tmp_path: Path) -> None:
    """The vertices and faces of a skin file are formatted once, when it is read."""
    skin = read_skin(_big_skin_file(tmp_path / "sheet.skn", 400))
    assert skin.vertex is not None and skin.face is not None
    assert format_value(skin.vertex) is format_value(skin.vertex)  # the remembered text
    assert format_value(skin.face) is format_value(skin.face)
    assert format_value(skin.vertex) == format_value(tuple(skin.vertex))  # as any list writes


def test_an_inlined_skin_keeps_its_place_in_the_model_file(tmp_path: Path) -> None:
    """Inlined, the skin is the model's own element: its file, line and attributes.

    Its numbers are the very lists the skin file was read into (so their remembered text
    is written); renaming the bodies edits the bones, and MuJoCo compiles the written model
    as the renamed model written canonically.
    """
    _big_skin_file(tmp_path / "sheet.skn", 400)
    text = (
        "<mujoco>\n<asset>\n"
        '<skin file="sheet.skn" rgba="1 0 0 1" inflate="0.01"/>\n</asset>\n'
        '<worldbody><body name="a"><geom size="0.1"/><body name="b"><geom size="0.1"/>'
        '<body name="c"><geom size="0.1"/></body></body></body></worldbody></mujoco>'
    )
    (tmp_path / "sheet.xml").write_text(text)
    model = load(tmp_path / "sheet.xml")
    (skin,) = inline_skin_files(model).elements[0].elements
    assert isinstance(skin, Skin) and skin.file is None and skin.layout is not None
    assert skin.layout.where() == (str(tmp_path / "sheet.xml"), 3)
    assert (skin.name, skin.rgba, skin.inflate) == ("sheet", (1.0, 0.0, 0.0, 1.0), 0.01)
    read = read_skin(tmp_path / "sheet.skn")
    assert skin.vertex is read.vertex and skin.children == read.children
    renamed = prefixed(model, "p_")
    written = dumps(renamed)
    assert f'vertex="{format_value(read.vertex)}"' in written
    assert loads(written, base_dir=tmp_path) == renamed
    canonical = dumps(renamed, canonical=True)
    assert (
        model_differences(
            mujoco.MjModel.from_xml_string(written), mujoco.MjModel.from_xml_string(canonical)
        )
        == []
    )
