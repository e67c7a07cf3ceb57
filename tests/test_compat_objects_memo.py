"""Objects made again and again (files read once, names planned once) against robosuite."""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import robosuite.models.objects as rs

from mjcf_model.compat import objects as ours
from tests.support.compat_objects import _OBJECT, assert_same_object


def test_primitives_of_other_sizes_and_names_match_robosuite() -> None:
    """Boxes of one shape but new sizes and names, made in turn, are robosuite's boxes."""
    sizes = np.random.default_rng(3).uniform(0.01, 0.05, size=(6, 3))
    for index, size in enumerate(sizes):
        name = f"box{index % 3}"
        assert_same_object(ours.BoxObject(name, size=size), rs.BoxObject(name, size=size))


def test_composites_made_again_match_robosuite() -> None:
    """A composite made twice, with one name and then another, is robosuite's both times."""
    spec = {
        "total_size": [0.1, 0.1, 0.05],
        "geom_types": ["box", "box"],
        "geom_sizes": [[0.1, 0.1, 0.01], [0.01, 0.1, 0.05]],
        "geom_locations": [[0, 0, 0], [0, 0, 0.02]],
    }
    for name in ("shelf", "shelf", "rack"):
        assert_same_object(ours.CompositeObject(name, **spec), rs.CompositeObject(name, **spec))


def test_cans_made_again_are_independent_and_match_robosuite() -> None:
    """Cans made in turn are robosuite's; changing one's elements leaves the next one alone."""
    first = ours.CanObject("can")
    first.get_obj().set("pos", "1 2 3")
    for name in ("can", "other"):
        assert_same_object(ours.CanObject(name), rs.CanObject(name))


def test_a_changed_file_is_read_again(tmp_path: Path) -> None:
    """An object file changed on disk gives the new document, as robosuite reads it."""
    path = tmp_path / "thing.xml"
    for scale in ("1 1 1", "2 2 2"):
        path.write_text(_OBJECT.format(scale=scale))
        stat = path.stat()  # the same size: the modification time tells them apart
        os.utime(path, ns=(stat.st_atime_ns, stat.st_mtime_ns + 10**9))
        mine = ours.MujocoXMLObject(str(path), name="thing")
        theirs = rs.MujocoXMLObject(str(path), name="thing")
        assert_same_object(mine, theirs)
        assert mine.asset[0].get("scale") == scale


def test_joints_given_by_arrays_match_robosuite(tmp_path: Path) -> None:
    """Joint attributes given as arrays (nothing to remember them by) are robosuite's."""
    path = tmp_path / "thing.xml"
    path.write_text(_OBJECT.format(scale="1 1 1"))
    for axis in ([0, 0, 1], [0, 1, 0]):
        joints = [{"type": "hinge", "axis": np.array(axis)}]
        theirs_joints = [{"type": "hinge", "axis": np.array(axis)}]
        mine = ours.MujocoXMLObject(str(path), name="t", joints=joints)
        theirs = rs.MujocoXMLObject(str(path), name="t", joints=theirs_joints)
        assert_same_object(mine, theirs)
        assert mine.get_obj().find("joint").get("axis") == " ".join(str(v) for v in axis)


def test_joint_values_equal_as_numbers_but_written_apart_match_robosuite(tmp_path: Path) -> None:
    """``True``, ``1`` and ``1.0`` are equal keys yet robosuite writes them apart; so do these."""
    path = tmp_path / "thing.xml"
    path.write_text(_OBJECT.format(scale="1 1 1"))
    for limited in (True, 1, 1.0):
        joints = [{"type": "hinge", "limited": limited, "range": "-1 1"}]
        mine = ours.MujocoXMLObject(str(path), name="t", joints=[dict(joints[0])])
        theirs = rs.MujocoXMLObject(str(path), name="t", joints=[dict(joints[0])])
        assert_same_object(mine, theirs)
        assert mine.get_obj().find("joint").get("limited") == theirs.get_obj().find("joint").get(
            "limited"
        )
