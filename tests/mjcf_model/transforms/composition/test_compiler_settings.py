"""Tests of ``mjcf_model.transforms.composition.compiler_settings``."""

from __future__ import annotations

import attrs
import mujoco
import pytest

from mjcf_model import attach
from mjcf_model.errors import MjcfValueError
from mjcf_model.nodes.compiler import Compiler
from mjcf_model.nodes.node_info import BASE_FIELDS
from mjcf_model.nodes.root import Mujoco
from mjcf_model.schema.namespaces import SCHEMA
from mjcf_model.serializers import loads
from mjcf_model.transforms.composition.conventions import (
    CONVERTED_SETTINGS,
    MODEL_WIDE_SETTINGS,
    PATH_SETTINGS,
)
from tests.conftest import printed_schema

# -- A child rewritten into a parent's compiler conventions compiles as the child alone. -------
#
# Every test compiles the child alone under its own ``<compiler>`` (the model-wide
# settings being the parent's) and the rewritten child under the parent's, and
# compares what MuJoCo made of every body, joint, geom, site, camera, tendon and
# actuator.


def test_the_settings_lists_cover_every_compiler_setting() -> None:
    """Each compiler attribute and child element is converted, a path, or model-wide."""
    listed = set(CONVERTED_SETTINGS) | PATH_SETTINGS | MODEL_WIDE_SETTINGS
    children = {key.split("/")[1] for key in SCHEMA if key.startswith("compiler/")}
    fields = {f.name for f in attrs.fields(Compiler)} - BASE_FIELDS
    assert listed == fields | children
    assert listed == set(SCHEMA["compiler"].attributes) | children
    installed = printed_schema()
    assert set(installed["compiler"]) | {"lengthrange"} <= listed
    assert not set(CONVERTED_SETTINGS) & PATH_SETTINGS
    assert not (set(CONVERTED_SETTINGS) | PATH_SETTINGS) & MODEL_WIDE_SETTINGS


# -- A child whose ``eulerseq`` MuJoCo rejects is refused by ``attach`` with an
#    ``MjcfValueError``.


CHILD = (
    '<mujoco><compiler eulerseq="{}"/><worldbody><body name="b" euler="10 20 30">'
    '<geom size="0.1"/></body></worldbody></mujoco>'
)


@pytest.mark.parametrize("sequence", ["xy", "xyzx"])
def test_an_eulerseq_of_other_than_three_axes_is_refused_as_mujoco_does(sequence: str) -> None:
    """MuJoCo rejects the child; attaching it says what MuJoCo reads instead of a bare error."""
    with pytest.raises(ValueError, match="XML Error"):
        mujoco.MjModel.from_xml_string(CHILD.format(sequence))
    with pytest.raises(MjcfValueError, match=rf"eulerseq='{sequence}'.*exactly 3 axes"):
        attach(Mujoco(), loads(CHILD.format(sequence)), prefix="c_")
