"""Compiling a model in memory.

:func:`compiled` hands MuJoCo the model's text and the bytes of every file it
names (MuJoCo's asset dictionary, gathered by :func:`mjcf_model.serializers.bundling.bundled`),
so nothing is written and the model may combine files from many folders.

>>> from mjcf_model import loads
>>> model = loads('<mujoco><worldbody><geom size="0.1"/></worldbody></mujoco>')
>>> compiled(model).ngeom
1
"""

from __future__ import annotations

import itertools
import os
from collections.abc import Mapping
from typing import TYPE_CHECKING

from mjcf_model.bridge.compile_errors import compile_error
from mjcf_model.caching import IdentityCache
from mjcf_model.nodes.asset import Skin
from mjcf_model.nodes.base import Element, Node
from mjcf_model.nodes.building import build_node
from mjcf_model.nodes.root import Mujoco
from mjcf_model.serializers.bundling import Bundle, bundled_on_disk
from mjcf_model.serializers.dumping import dumps
from mjcf_model.serializers.skins import skin_file_bytes
from mjcf_model.tree.traversal import with_children
from mjcf_model.values.encoding import for_mujoco

if TYPE_CHECKING:
    import mujoco

__all__ = ["compiled"]


#: The fewest numbers an inline skin holds for :func:`compiled` to hand it over as a file.
_SKIN_FILE_NUMBERS = 3000


def _skins_as_files(model: Mujoco, files: dict[str, bytes]) -> tuple[Mujoco, dict[str, bytes]]:
    """``model`` with each big named inline skin given as a binary skin file in ``files``.

    MuJoCo reads a skin's float32 arrays from a file in a fraction of the time it
    parses them as text (a scaled copy of dm_control's dog writes 4.6 MB of skin
    numbers), and compiles the same model: the file holds the values MuJoCo would
    have rounded the text to (only ``paths`` records the file's name,
    ``mjcf-model-skin-0.skn``). An unnamed skin stays inline (MuJoCo would name it
    after the file), and so does one the format cannot hold (see
    :func:`mjcf_model.serializers.skins.skin_file_bytes`).
    """
    added = dict(files)
    made = iter(f"mjcf-model-skin-{n}.skn" for n in itertools.count())

    def as_file(element: Node) -> Node:
        if not isinstance(element, Skin) or element.name is None or element.file is not None:
            return element
        data = None if len(element.vertex or ()) < _SKIN_FILE_NUMBERS else skin_file_bytes(element)
        if data is None:
            return element
        name = next(name for name in made if name not in added)
        added[name] = data
        changes = {"file": name, "vertex": None, "texcoord": None, "face": None}
        return build_node(Skin, {**changes, "children": ()}, element)

    sections = [  # skins stand only in these top-level sections
        with_children(section, [as_file(child) for child in section.children])
        if isinstance(section, Element) and getattr(section, "tag", "") in ("asset", "deformable")
        else section
        for section in model.children
    ]
    changed = with_children(model, sections)
    return (model, files) if changed is model else (changed, added)


def compiled(model: Mujoco, *, assets: Mapping[str, bytes] | None = None) -> mujoco.MjModel:
    r"""Compile ``model`` with MuJoCo in memory: nothing is written.

    Every file the model names is found where its provenance says it is
    (see :mod:`mjcf_model.files.provenance`): a loaded model's files resolve from its
    folder, the files of models attached from other folders from theirs. A
    model built in code resolves relative paths from the working folder, or
    takes the files from ``assets``. MuJoCo reads a file that exists on disk
    itself, by its absolute path (so its cache of decoded meshes and textures
    serves every compile of the same file); the text of asset ``<model>`` files
    and whatever ``assets`` gives go through MuJoCo's asset dictionary. The
    compiler's ``meshdir``, ``texturedir``, ``assetdir`` and ``strippath`` are
    resolved before MuJoCo sees the model.

    Args:
        model: The model.
        assets: File contents by the path the model writes (``"box.stl"``, or
            with the compiler folder, ``"meshes/box.stl"``).

    Raises:
        MjcfCompileError: MuJoCo rejects the model; the message is MuJoCo's, after the
            file, line and element path of the element it rejects
            (:mod:`mjcf_model.bridge.compile_errors`).
        MjcfAssetError: A file cannot be read and is not in ``assets``.

    Examples:
        >>> from mjcf_model import loads
        >>> model = loads('<mujoco><asset><mesh name="m" file="tet.obj"/></asset>'
        ...               '<worldbody><geom type="mesh" mesh="m"/></worldbody></mujoco>')
        >>> points = "v 0 0 0 \n v 1 0 0 \n v 0 1 0 \n v 0 0 1 \n"
        >>> faces = "f 1 2 3 \n f 1 2 4 \n f 1 3 4 \n f 2 3 4"
        >>> tetrahedron = (points + faces).encode()
        >>> compiled(model, assets={"tet.obj": tetrahedron}).mesh_vertnum.tolist()
        [4]

    """
    import mujoco

    if assets:
        bundle, text, files = _written(model, dict(assets))
    else:  # a model compiled again (a reset, a sweep) is written once
        bundle, text, files = _WRITTEN.recall_for(model, lambda: _written(model, {}), os.getcwd())
        if files:  # file contents were read: read them again next time
            _WRITTEN.pop((id(model), os.getcwd()), None)
    try:
        return mujoco.MjModel.from_xml_string(for_mujoco(text), files)
    except ValueError as error:
        raise compile_error(str(error), model, bundle, text) from None


def _written(model: Mujoco, assets: dict[str, bytes]) -> tuple[Bundle, str, dict[str, bytes]]:
    """The bundle of ``model``, the text MuJoCo compiles and the files it reads from memory."""
    bundle = bundled_on_disk(model, assets)
    given, files = _skins_as_files(bundle.model, bundle.files)
    return bundle, dumps(given), files


#: What :func:`compiled` wrote for the last few models given no assets, by model and working
#: folder (a relative path of a model built in code resolves from it); kept only where
#: MuJoCo reads every file itself, by absolute path, so it reads what is there each time.
_WRITTEN: IdentityCache[tuple[Bundle, str, dict[str, bytes]]] = IdentityCache(8)
