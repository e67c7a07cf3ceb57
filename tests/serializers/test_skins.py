"""Tests of ``serializers.skins``."""

from __future__ import annotations

import itertools

import mujoco
import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from serializers.skins import float32_as_written
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
