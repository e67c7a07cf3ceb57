"""Names MuJoCo makes while reading a model, and how renaming their source renames them.

Some elements declare names that never appear in the text, and other elements
may refer to them:

* ``<replicate count="N" sep="s">`` copies its contents ``N`` times and gives
  each name a suffix: ``sep`` and the copy index, zero-padded to the width of
  ``N`` (``post`` becomes ``post00`` ... ``post11`` for ``count="12"``). Nested
  replicates add the inner suffix first (``cell-21``: index 2 inside, 1
  outside). An element outside that refers to a copied one is copied with it
  and gets the same suffix.
* ``<flexcomp name="rope">`` makes the bodies ``rope_0``, ``rope_1``, ...
  (``rope_0_1_1`` with ``dof="trilinear"`` or ``"quadratic"``; pinned vertices
  make no body); inside a replicate the replicate's suffix follows.
* ``<attach prefix="g_">`` brings in the attached elements' names with ``g_``
  in front. With a ``model`` they are the child model's names; without one
  (MuJoCo 4.0; MuJoCo 3.9 requires ``model``) it copies a body or frame of the
  same model, so the part after the prefix is one of this model's names.

Renaming the source renames what it makes: :class:`GeneratedNames` finds the
source of such a name, so a reference to ``rope_3`` follows the flexcomp
``rope``, one to ``post03`` the body ``post`` and one to ``g_palm`` the
attach's prefix. :func:`declarations` lists the names an element declares,
including those read from files (an asset ``<model>`` is named by its file's
root ``model`` attribute, see :func:`model_file_name`).

>>> from mjcf_model import loads
>>> model = loads('''<mujoco><worldbody><replicate count="12" sep="_">
...   <body name="post"><geom size="1"/></body></replicate>
...   <flexcomp name="rope" type="grid" count="4 1 1" spacing="1 1 1" dim="1"/>
... </worldbody></mujoco>''')
>>> generated = GeneratedNames.of(model)
>>> generated.source("body", "post_07")
Source(namespace='body', name='post', suffix='_07')
>>> generated.source("body", "rope_3")
Source(namespace='flex', name='rope', suffix='_3')
>>> generated.source("body", "post_12") is None
True
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from functools import lru_cache
from pathlib import Path

import attrs

from mjcf_model.errors import MjcfAssetError, MjcfError
from mjcf_model.files.provenance import Folders, file_stem
from mjcf_model.nodes.base import AnyElement, get_attribute
from mjcf_model.nodes.root import Mujoco
from mjcf_model.schema.namespaces import SCHEMA
from mjcf_model.serializers import load
from mjcf_model.tree.traversal import keyed_walk

__all__ = [
    "DECLARING_KEYS",
    "MAIN_CLASS",
    "DEFAULT_MODEL_NAME",
    "SAME_MODEL_ATTACH",
    "GeneratedNames",
    "Source",
    "declarations",
    "model_file_name",
    "copy_suffix",
    "model_file_path",
]

#: The name MuJoCo gives a model whose root has no ``model`` attribute.
DEFAULT_MODEL_NAME = "MuJoCo Model"

#: One replicate: its separator, its count and the width of the index.
_Level = tuple[str, int, int]
#: The replicates around an element, innermost first.
_Chain = tuple[_Level, ...]

#: ``rename(namespace, name)``: the new name, or the same one to keep it.
Renamer = Callable[[str, str], str]

#: Flexcomp ``dof`` values whose bodies carry three indices (``rope_0_1_1``).
_GRID_DOFS = frozenset({"trilinear", "quadratic"})

#: Elements whose name, when not written, is the stem of their ``file``.
_NAMED_BY_FILE = frozenset(
    {"asset/mesh", "asset/texture", "asset/hfield", "asset/skin", "deformable/skin"}
)

#: The schema keys of elements that declare a name (the others need no look).
DECLARING_KEYS = frozenset(key for key, spec in SCHEMA.items() if spec.declares)

#: The top-level default class, as (name, namespace): MuJoCo does not allow renaming it.
MAIN_CLASS = ("main", "class")

#: The attributes of an ``<attach>`` without ``model``: they name this model's body or frame.
SAME_MODEL_ATTACH = attrs.evolve(
    SCHEMA["body/attach"],
    references={**SCHEMA["body/attach"].references, "body": "body", "frame": "frame"},
)


@attrs.frozen
class Source:
    """Where a generated name comes from: ``name`` (in ``namespace``) followed by ``suffix``."""

    #: The namespace of the name that makes it.
    namespace: str
    #: The name that makes it.
    name: str
    #: What MuJoCo puts after that name.
    suffix: str


def model_file_path(file: str, base_dir: Path | None) -> Path:
    """Where MuJoCo reads an asset ``<model file>``: the model's folder (no compiler folder).

    Examples:
        >>> model_file_path("parts/arm.xml", Path("/robots"))
        PosixPath('/robots/parts/arm.xml')

    """
    return Folders().resolve(file, "model", base_dir)


def model_file_name(path: Path) -> str:
    """The name MuJoCo gives an asset ``<model>`` without ``name``: its file's root ``model``.

    Not the file's stem: MuJoCo 3.9 and 4.0 both name it by the ``model``
    attribute of the file's ``<mujoco>`` root, and ``"MuJoCo Model"`` when the
    root has none.

    Raises:
        MjcfAssetError: The file cannot be read or is not MJCF.

    Examples:
        >>> import tempfile
        >>> with tempfile.TemporaryDirectory() as folder:
        ...     path = Path(folder) / "gripper_v2.xml"
        ...     _ = path.write_text('<mujoco model="gripper"/>')
        ...     model_file_name(path)
        'gripper'

    """
    try:
        stat = path.stat()
    except OSError as error:
        raise _unreadable(path, error) from None
    return _root_model_name(str(path), stat.st_mtime_ns, stat.st_size)


def declarations(
    element: AnyElement, key: str | None, *, base_dir: Path | None = None
) -> Iterator[tuple[str, str, str]]:
    """``(attribute, namespace, name)`` for each name ``element`` declares (file names too).

    An asset ``<model>`` without ``name`` is named by its file's root (read from
    ``base_dir``, the working folder when ``None``; :class:`MjcfAssetError` when
    it cannot be read).

    Examples:
        >>> from mjcf_model import Mesh
        >>> list(declarations(Mesh(file="parts/hand.stl"), "asset/mesh"))
        [('name', 'mesh', 'hand')]

    """
    if key is None or key not in DECLARING_KEYS:
        return
    for attribute, namespace in SCHEMA[key].declares.items():
        name = get_attribute(element, attribute)
        if isinstance(name, str) and name and (name, namespace) != MAIN_CLASS:
            yield attribute, namespace, name
        elif name is None and key in _NAMED_BY_FILE:
            file = get_attribute(element, "file")
            if isinstance(file, str) and file:
                yield attribute, namespace, file_stem(file)
        elif name is None and key == "asset/model":
            file = get_attribute(element, "file")
            if isinstance(file, str) and file:
                named = model_file_name(model_file_path(file, base_dir))
                if named:
                    yield attribute, namespace, named


def _unreadable(path: Path, error: Exception) -> MjcfAssetError:
    return MjcfAssetError(
        f"cannot read the asset <model> file {str(path)!r} to find the name MuJoCo gives it "
        f"(its root's model attribute): {error}; give the <model> a name, or load the model "
        "from its folder so that base_dir locates the file"
    )


@lru_cache(maxsize=256)
def _root_model_name(path: str, _mtime: int, _size: int) -> str:

    try:
        root = load(path)
    except (OSError, MjcfError) as error:
        raise _unreadable(Path(path), error) from None
    name = get_attribute(root, "model")
    return DEFAULT_MODEL_NAME if name is None else str(name)


def copy_suffix(replicate: AnyElement, index: int) -> str:
    """The suffix MuJoCo gives copy ``index`` of a ``<replicate>``.

    It is ``sep``, then the index zero-padded to the width of ``count``.

    Examples:
        >>> from mjcf_model.nodes.base import GenericElement
        >>> replicate = GenericElement(tag="replicate", attributes={"count": "12", "sep": "_"})
        >>> copy_suffix(replicate, 3)
        '_03'

    """
    count = _count(replicate) or 1
    return str(get_attribute(replicate, "sep") or "") + str(index).zfill(len(str(count)))


def _count(element: AnyElement) -> int | None:
    try:
        value = get_attribute(element, "count")
        return int(str(value)) if value is not None else None
    except (MjcfError, ValueError):
        return None


def _chain_suffix(chain: _Chain, text: str) -> bool:
    """Whether ``text`` is a suffix the replicates of ``chain`` give (indices in range)."""
    at = 0
    for sep, count, width in chain:
        if not text.startswith(sep, at):
            return False
        digits = text[at + len(sep) : at + len(sep) + width]
        if len(digits) != width or not digits.isdigit() or int(digits) >= count:
            return False
        at += len(sep) + width
    return at == len(text)


def _chain_length(chain: _Chain) -> int:
    return sum(len(sep) + width for sep, _, width in chain)


@attrs.define
class _Attachment:
    #: The attach element's ``prefix``.
    prefix: str
    #: Whether it copies part of the same model (no ``model`` attribute).
    same_model: bool


class GeneratedNames:
    """The name generators of one tree: replicates, flexcomps and attachments.

    Build it with :meth:`of`; :meth:`source` tells where a name MuJoCo makes
    comes from, :meth:`renamed` gives its new name after a renaming.

    Examples:
        >>> from mjcf_model import loads
        >>> model = loads('<mujoco><worldbody><flexcomp name="rope" type="grid" '
        ...               'count="4 1 1" spacing="1 1 1" dim="1"/></worldbody></mujoco>')
        >>> GeneratedNames.of(model).renamed("body", "rope_2", lambda ns, n: "p_" + n, None)
        'p_rope_2'

    """

    def __init__(self) -> None:
        #: The names the tree declares, by namespace, with the replicates around each.
        self.declared: dict[str, dict[str, set[_Chain]]] = {}
        #: Flexcomp names, with the replicates around them and whether bodies have 3 indices.
        self.flexcomps: dict[str, set[tuple[_Chain, bool]]] = {}
        #: Every distinct chain of replicates, the empty one first.
        self.chains: dict[_Chain, None] = {(): None}
        #: The ``<attach>`` elements, in document order.
        self.attachments: list[_Attachment] = []

    @classmethod
    def of(cls, node: AnyElement, base_dir: Path | None = None) -> GeneratedNames:
        """The generators in ``node`` (a model's own ``base_dir`` locates ``<model>`` files).

        Examples:
            >>> from mjcf_model import Attach, Body
            >>> found = GeneratedNames.of(Body(name="b", children=[Attach(model="m", prefix="g_")]))
            >>> sorted(found.declared["body"]), len(found.attachments)
            (['b'], 1)

        """
        if isinstance(node, Mujoco) and base_dir is None:
            base_dir = node.base_dir
        found = cls()
        for element, key, chain in _chained_walk(node):
            if key in DECLARING_KEYS:
                for _, namespace, name in declarations(element, key, base_dir=base_dir):
                    found.declared.setdefault(namespace, {}).setdefault(name, set()).add(chain)
            if key == "body/flexcomp":
                flex = get_attribute(element, "name")
                if isinstance(flex, str) and flex:
                    grid = str(get_attribute(element, "dof") or "").strip() in _GRID_DOFS
                    found.flexcomps.setdefault(flex, set()).add((chain, grid))
            elif key == "body/attach":
                prefix = get_attribute(element, "prefix")
                same = get_attribute(element, "model") is None
                found.attachments.append(_Attachment(str(prefix or ""), same))
            found.chains.setdefault(chain)
        return found

    def source(self, namespace: str, name: str) -> Source | None:
        """Where the ``name`` MuJoCo makes comes from; ``None`` for a declared or unknown name.

        Attachments are not sources here (see :meth:`renamed`).

        Examples:
            >>> from mjcf_model import loads
            >>> model = loads('<mujoco><worldbody><replicate count="3" sep="-">'
            ...               '<site name="s"/></replicate></worldbody></mujoco>')
            >>> GeneratedNames.of(model).source("site", "s-2")
            Source(namespace='site', name='s', suffix='-2')

        """
        declared = self.declared.get(namespace, {})
        if name in declared:
            return None
        for chain in self.chains:
            length = _chain_length(chain)
            if length >= len(name) or not _chain_suffix(chain, name[len(name) - length :]):
                continue
            head, tail = name[: len(name) - length], name[len(name) - length :]
            chains = declared.get(head)
            if chain and chains is not None and chain in chains:
                return Source(namespace, head, tail)
            if namespace == "body":
                found = self._flexcomp_source(head, chain)
                if found is not None:
                    return Source("flex", found[0], found[1] + tail)
        return None

    def _flexcomp_source(self, head: str, chain: _Chain) -> tuple[str, str] | None:
        for indices, grid in ((1, False), (3, True)):
            parts = head.rsplit("_", indices)
            indexed = len(parts) == indices + 1 and all(part.isdigit() for part in parts[1:])
            if indexed and (chain, grid) in self.flexcomps.get(parts[0], ()):
                return parts[0], head[len(parts[0]) :]
        return None

    def renamed(self, namespace: str, name: str, rename: Renamer, attach_prefix: str | None) -> str:
        """The new name of ``name`` when the names it is made from are renamed by ``rename``.

        ``attach_prefix`` is what each ``<attach>``'s ``prefix`` gains (``None``:
        nothing). A name that is declared, or made by nothing, is returned as it is.

        Examples:
            >>> from mjcf_model import Attach, Body
            >>> found = GeneratedNames.of(Body(children=[Attach(model="m", prefix="g_")]))
            >>> found.renamed("joint", "g_elbow", lambda ns, n: n, "p_")
            'p_g_elbow'

        """
        if name in self.declared.get(namespace, {}):
            return name
        found = self.source(namespace, name)
        if found is not None:
            return rename(found.namespace, found.name) + found.suffix
        for attachment in self.attachments:
            if attachment.same_model and not attachment.prefix:
                continue  # copies named like their originals: MuJoCo rejects the duplicates
            if name.startswith(attachment.prefix) and len(name) > len(attachment.prefix):
                rest = name[len(attachment.prefix) :]
                new_prefix = (attach_prefix or "") + attachment.prefix
                return new_prefix + (rename(namespace, rest) if attachment.same_model else rest)
        return name

    def renames_bodies(self, rename: Renamer, attach_prefix: str | None) -> bool:
        """Whether ``rename`` (with ``attach_prefix``) changes the name of any body.

        Examples:
            >>> from mjcf_model import Body
            >>> found = GeneratedNames.of(Body(name="b"))
            >>> found.renames_bodies(lambda ns, n: n, None), found.renames_bodies(str.__add__, None)
            (False, True)

        """
        bodies = self.declared.get("body", {})
        if any(rename("body", name) != name for name in bodies):
            return True
        if any(rename("flex", name) != name for name in self.flexcomps):
            return True
        return bool(attach_prefix and self.attachments)


def _chained_walk(node: AnyElement) -> Iterator[tuple[AnyElement, str | None, _Chain]]:
    """:func:`keyed_walk` with the replicates around each element, innermost first."""
    below: list[_Chain] = []
    for element, key, ancestors in keyed_walk(node):
        depth = len(ancestors)
        del below[depth:]
        chain = below[-1] if below else ()
        inner = chain
        if key == "body/replicate":
            count = _count(element)
            sep = get_attribute(element, "sep")
            if count is not None and count > 0:
                inner = ((str(sep or ""), count, len(str(count))), *chain)
        below.append(inner)
        yield element, key, chain
