"""Tests of ``mjcf_model.serializers.locations``: where an element stands, for errors."""

from __future__ import annotations

import errno

from mjcf_model import Body, Geom, Mujoco, Worldbody, loads
from mjcf_model.errors import MjcfAssetError, MjcfValueError
from mjcf_model.nodes.base import Comment
from mjcf_model.serializers.locations import element_at, element_path, located_in, read_from

TEXT = """<mujoco>
  <worldbody>
    <!-- the floor -->
    <geom name="floor" size="1 1 0.1" type="plane"/>
    <body name="arm">
      <geom size="0.1"/>
      <geom size="0.2"/>
    </body>
  </worldbody>
</mujoco>
"""


def test_element_paths_count_elements_of_a_tag_and_prefer_names() -> None:
    """A step is ``tag[@name=...]`` for a named element, else ``tag[n]``.

    ``n`` counts from 1 the elements of that tag (comments skipped); an index path past
    the children, or to a comment, finds nothing.
    """
    model = loads(TEXT)
    arm = model.worldbody.bodies[0]
    second = arm.geoms[1]
    assert element_path(model, second) == "/mujoco/worldbody/body[@name='arm']/geom[2]"
    assert element_path(model, model.worldbody.geoms[0]) == "/mujoco/worldbody/geom[@name='floor']"
    assert element_path(model, Geom()) is None  # not in the model (identity, not equality)
    children = model.worldbody.children
    comment = next(i for i, c in enumerate(children) if isinstance(c, Comment))
    assert element_at(model, (0, comment)) is None  # a comment is no element
    assert element_at(model, (0, 99)) is None
    found = element_at(model, (0, children.index(arm), 0))
    assert found is not None and found[0] is arm.geoms[0]


def test_read_from_names_the_file_and_line_of_a_loaded_element() -> None:
    """A loaded element knows its file and line; one built in code knows neither."""
    model = loads(TEXT, filename="arm.xml")
    assert read_from(model.worldbody.bodies[0].geoms[1]) == ("arm.xml", 7)
    built = Mujoco(children=[Worldbody(children=[Body(name="b")])])
    assert read_from(built.worldbody.bodies[0]) == (None, None)


def test_located_in_fills_only_what_the_error_lacks_and_keeps_an_oserrors_reason() -> None:
    """File, line and path come from the element unless the error has them.

    The errno, reason and file name of a file error travel with it; the class stays.
    """
    model = loads(TEXT, filename="arm.xml")
    geom = model.worldbody.bodies[0].geoms[0]
    problem = MjcfAssetError("cannot read 'hand.stl'")
    problem.errno, problem.strerror, problem.filename = errno.ENOENT, "No such file", "hand.stl"
    located = located_in(problem, model, geom)
    assert type(located) is MjcfAssetError
    assert (located.file, located.line) == ("arm.xml", 6)
    assert located.path == "/mujoco/worldbody/body[@name='arm']/geom"
    assert (located.errno, located.strerror, located.filename) == (
        errno.ENOENT,
        "No such file",
        "hand.stl",
    )
    kept = located_in(MjcfValueError("bad", file="other.xml", line=3), model, geom)
    assert (kept.file, kept.line) == ("other.xml", 3)
