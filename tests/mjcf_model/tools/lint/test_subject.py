"""Tests of ``mjcf_model.tools.lint.subject``: placing compiled rows in the user's file."""

from __future__ import annotations

from mjcf_model import loads
from mjcf_model.tools.lint.subject import Subject


def test_a_finding_names_the_file_line_and_path_of_its_compiled_row() -> None:
    """A joint's row is placed at its element; a row a replicate made has no element."""
    text = (
        "<mujoco>\n<worldbody>\n<body>\n<joint name='j'/>\n<geom size='1'/>\n</body>\n"
        "<replicate count='2' offset='1 0 0'><body><joint/><geom size='1'/></body></replicate>\n"
        "</worldbody>\n</mujoco>"
    )
    subject = Subject(loads(text, filename="m.xml"))
    finding = subject.finding("R201", ("joint", 0), "message")
    assert (finding.file, finding.line, finding.path) == (
        "m.xml",
        4,
        "/mujoco/worldbody/body/joint[@name='j']",
    )
    assert subject.element(("joint", 1)) is None
    whole = subject.finding("R201", ("joint", 2), "message")
    assert (whole.line, whole.path) == (1, "/mujoco")
    assert subject.name("joint", 0) == "'j'" and subject.name("joint", 1) == "joint 1"
