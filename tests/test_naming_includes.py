"""An ``<include>`` anywhere in a tree is read as an include, and renaming refuses it.

Its file's elements are not in the tree, so their names could not be renamed: the
refusal says how to load the model instead.
"""

from __future__ import annotations

import pytest

from mjcf_model import prefixed
from mjcf_model.errors import MjcfValueError
from serializers import loads

SAID = r"cannot rename names in a model with <include> elements: .*inline_includes=True"


@pytest.mark.parametrize(
    "where",
    ["<worldbody><body name='b'>{}</body></worldbody>", "<asset>{}</asset>", "{}"],
    ids=["in a body", "in a section", "at the top"],
)
def test_an_include_is_refused_wherever_it_stands(where: str) -> None:
    """Prefixing a model holding an ``<include>`` raises, saying to inline includes."""
    include = '<include file="part.xml"/>'
    model = loads(f"<mujoco>{where.format(include)}</mujoco>")
    with pytest.raises(MjcfValueError, match=SAID):
        prefixed(model, "p_")
