"""Writing MJCF: nodes into text and files.

The mirror of :mod:`mjcf_model.serializers.loading`. A loaded model is written as it was
read (:mod:`mjcf_model.serializers.kept_format`): each element that carries a
:class:`~mjcf_model.serializers.layout.Layout` is written as its source text, with only what
changed edited in place, and an element added in code is written in the
canonical form, indented to fit. The canonical form (:mod:`mjcf_model.serializers.canonical`;
``canonical=True``, and every model built in code) writes each element on its
own line, indented by ``indent``. Attribute values are formatted by
:func:`mjcf_model.values.format_value`, the one place numbers become text, and
come out in the order they had in the source.

>>> from mjcf_model import Geom, Mujoco, Worldbody
>>> print(dumps(Mujoco(children=[Worldbody(children=[Geom(size=[0.1])])])), end="")
<mujoco>
  <worldbody>
    <geom size="0.1"/>
  </worldbody>
</mujoco>
"""

from __future__ import annotations

import contextlib
import os
import tempfile
from pathlib import Path
from typing import IO

from mjcf_model.errors import Advice, MjcfAssetError, MjcfValueError
from mjcf_model.files.provenance import Folders, file_references, relocated
from mjcf_model.nodes.base import Element, Node
from mjcf_model.nodes.root import Mujoco
from mjcf_model.serializers.canonical import attribute_texts, write_canonical
from mjcf_model.serializers.kept_format import write_kept
from mjcf_model.serializers.loading import loads
from mjcf_model.tree.queries import find_all
from mjcf_model.tree.traversal import keyed_walk
from mjcf_model.values.encoding import encoded

__all__ = [
    "attribute_texts",
    "dump",
    "dumps",
    "inlined_includes",
    "relocated_for",
    "write_atomically",
]

#: What to do with a model whose included files would name other files written elsewhere.
WRITTEN_ELSEWHERE = Advice(
    "load it with inline_includes=True, or export it",
    "write it into the model's own folder, or use 'mjcf-model export' to gather its files",
)


def dumps(node: Node, *, indent: str = "  ", canonical: bool = False) -> str:
    r"""Write a node (usually a whole :class:`~mjcf_model.Mujoco`) as MJCF text.

    A loaded node is written as it was read (line breaks, indentation, quotes,
    number spellings, comments, the XML declaration), with only what was
    changed since rewritten; a node built in code is written in the canonical form.

    Args:
        node: The node to write.
        indent: The indentation of one nesting level in the canonical form.
        canonical: Write the canonical form even for a loaded node, as a formatter would.

    Examples:
        >>> from mjcf_model import Site
        >>> dumps(Site(name="tip", pos=(0, 0, 0.1)))
        '<site name="tip" pos="0 0 0.1"/>\n'
        >>> from mjcf_model import loads
        >>> model = loads("<mujoco>\n\n  <option timestep='2e-3'/>\n</mujoco>\n")
        >>> dumps(model)
        "<mujoco>\n\n  <option timestep='2e-3'/>\n</mujoco>\n"
        >>> dumps(model, canonical=True)
        '<mujoco>\n  <option timestep="0.002"/>\n</mujoco>\n'

    """
    out: list[str] = []
    if canonical or not isinstance(node, Element) or node.layout is None:
        write_canonical(node, indent, out)
    else:
        write_kept(node, out)
    return "".join(out)


def dump(
    node: Node,
    target: str | os.PathLike[str] | IO[str],
    *,
    indent: str = "  ",
    canonical: bool = False,
) -> None:
    r"""Write a node to a file path or an open text file.

    Writing a loaded model to a path in another folder (or to an open file that
    names its path) relocates it: relative
    file paths (meshes, textures, includes...) are rewritten to name the same
    files from the new folder (:func:`mjcf_model.files.provenance.relocated`). Written
    back to its own folder, the text is unchanged. A model built in code has no
    folder of its own: its paths are written as they are.

    Writing to a path is atomic: the text goes to a temporary file beside the
    target, which then replaces it. If anything fails, the old file is untouched
    and no partial file is left. Missing folders on the way to the path are
    created, as :func:`mjcf_model.serializers.export` creates them. The text is written as
    :func:`dumps` gives it (line breaks are not translated), encoded as UTF-8.

    Args:
        node: The node to write.
        target: A path, or a file object opened for writing text.
        indent: The indentation of one nesting level in the canonical form.
        canonical: Write the canonical form even for a loaded node (see :func:`dumps`).

    Raises:
        MjcfAssetError: The path's folder cannot be created or written into (a file
            is in the way, no permission); the message names the folder.

    Examples:
        >>> import tempfile, pathlib
        >>> from mjcf_model import Mujoco
        >>> path = pathlib.Path(tempfile.mkdtemp()) / "out" / "scene.xml"
        >>> dump(Mujoco(model="m"), path)
        >>> path.read_text()
        '<mujoco model="m"/>\n'

    """
    if not isinstance(target, (str, os.PathLike)):
        name = getattr(target, "name", None)  # an open file names its path, as load reads it
        if isinstance(name, str) and not name.startswith("<"):
            node = relocated_for(node, Path(name).parent)
        target.write(dumps(node, indent=indent, canonical=canonical))
        return
    path = Path(target)
    text = dumps(relocated_for(node, path.parent), indent=indent, canonical=canonical)
    write_atomically(text, path)


def write_atomically(data: str | bytes, target: str | os.PathLike[str]) -> None:
    """Write ``data`` (text as UTF-8, line breaks as they are) to ``target``, all or nothing.

    The data goes to a temporary file beside the target, which then replaces it
    (keeping its permissions); if anything fails, the old file is untouched and no
    partial file is left. Missing folders on the way to the target are created.

    Raises:
        MjcfAssetError: The target's folder cannot be created or written into (a
            file is in the way, no permission); the message names the folder.

    Examples:
        >>> import tempfile, pathlib
        >>> path = pathlib.Path(tempfile.mkdtemp()) / "new" / "out.xml"
        >>> write_atomically("<mujoco/>", path)
        >>> path.read_text()
        '<mujoco/>'

    """
    path = Path(os.path.realpath(target))  # through a link: the file it names is written
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        handle, temporary = tempfile.mkstemp(
            prefix=f".{path.name}.", suffix=".tmp", dir=path.parent
        )
    except OSError as error:
        raise MjcfAssetError(
            f"cannot write {str(target)!r}: {_folder_problem(path.parent, error)}; "
            "nothing was written"
        ) from None
    try:
        with os.fdopen(handle, "wb") as stream:
            stream.write(encoded(data) if isinstance(data, str) else data)
            stream.flush()
            os.fsync(stream.fileno())
        with contextlib.suppress(OSError):  # an old file's mode, else the umask's
            os.chmod(temporary, path.stat().st_mode & 0o7777 if path.exists() else _new_mode())
        os.replace(temporary, path)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(temporary)
        raise


def _folder_problem(folder: Path, error: OSError) -> str:
    """Why ``folder`` cannot be created or written into: the file in its way, or ``error``."""
    for existing in (folder, *folder.parents):
        if os.path.lexists(existing):
            if not existing.is_dir():
                return f"{str(existing)!r} is a file, not a folder; move it, or write elsewhere"
            break
    return (
        f"its folder {str(folder)!r} cannot be created or written into "
        f"({error.strerror or error}); choose a folder you can write to"
    )


def _new_mode() -> int:
    """The mode ``open`` gives a new file: 0o666 less the process's umask."""
    mask = os.umask(0)
    os.umask(mask)
    return 0o666 & ~mask


def relocated_for(node: Node, folder: Path) -> Node:
    """A loaded model with its paths rewritten to resolve from ``folder``; other nodes as given."""
    if isinstance(node, Mujoco) and node.base_dir is not None:
        return _relocated(node, folder)
    return node


def _relocated(model: Mujoco, folder: Path) -> Mujoco:
    """``model`` with its paths rewritten to resolve from ``folder``.

    A kept ``<include>`` is not rewritten, and its file may set the compiler's
    folders: they are read from the whole model. A path in an included file that
    MuJoCo found under the main model's folder is looked for under the new folder
    once the model moves: that raises.
    """
    if not any(key == "include" for _, key, _ in keyed_walk(model)):
        return relocated(model, folder)
    whole = inlined_includes(model)
    moved = relocated(model, folder, source=Folders.of(whole))
    before = [r.path for r in file_references(whole)]
    after = list(file_references(inlined_includes(moved)))
    for reference, path in zip(after, before, strict=False):
        if reference.path != path:
            raise MjcfValueError(
                f"an included file names {reference.text!r}, found under the model's folder "
                f"({str(path)!r}); written elsewhere the model would look for "
                f"{str(reference.path)!r}",
                advice=WRITTEN_ELSEWHERE,
            )
    if len(after) != len(before):
        raise MjcfValueError(
            "written elsewhere, the model's included files would name other files",
            advice=WRITTEN_ELSEWHERE,
        )
    return moved


def inlined_includes(model: Mujoco) -> Mujoco:
    """``model`` with kept ``<include>`` elements replaced by their files' elements.

    The files are found from the model's ``base_dir`` (a model built in code:
    the working folder), as :func:`mjcf_model.serializers.load` with ``inline_includes``
    finds them.

    Examples:
        >>> from mjcf_model import loads
        >>> model = loads("<mujoco><worldbody/></mujoco>")
        >>> inlined_includes(model) is model
        True

    """
    # the tree's index answers at once where there is no <include> at all (the usual case)
    if not find_all(model, "include") or not any(
        key == "include" for _, key, _ in keyed_walk(model)
    ):
        return model
    base = model.base_dir if model.base_dir is not None else Path(os.getcwd())
    return loads(dumps(model), inline_includes=True, base_dir=base)
