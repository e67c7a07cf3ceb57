"""Files of scenes using MuJoCo's ``<attach>``: written into a folder, compiled both ways."""

from __future__ import annotations

from pathlib import Path

import mujoco

from mjcf_model import compiled, inlined_attachments
from mjcf_model.serializers import load


def written(folder: Path, files: dict[str, str]) -> Path:
    """Write ``files`` (name: text) into ``folder``; the path of the first one."""
    for name, text in files.items():
        (folder / name).write_text(text, encoding="utf-8")
    return folder / next(iter(files))


def attached_body(folder: Path, child: str) -> tuple[mujoco.MjModel, mujoco.MjModel]:
    """MuJoCo's compilation of a scene attaching body ``b`` of ``child``, and of its expansion."""
    scene = written(
        folder,
        {
            "scene.xml": '<mujoco><asset><model name="c" file="child.xml"/></asset><worldbody>'
            '<body name="holder"><attach model="c" body="b" prefix="p_"/></body></worldbody>'
            "</mujoco>",
            "child.xml": child,
        },
    )
    return mujoco.MjModel.from_xml_path(str(scene)), compiled(inlined_attachments(load(scene)))
