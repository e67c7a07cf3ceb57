"""Tests of ``mjcf_model.compat.objects.habits``."""

from __future__ import annotations

import os
from pathlib import Path

import robosuite.models.objects as rs

from mjcf_model.compat import objects as ours
from tests.support.compat_objects import _OBJECT, assert_same_object

# -- Objects made again and again (files read once, names planned once) against robosuite. -----


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
