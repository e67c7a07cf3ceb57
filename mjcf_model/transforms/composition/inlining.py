"""MuJoCo's ``<attach>`` meta-element expanded into plain elements: :func:`inlined_attachments`.

``<attach model="m" body="b" prefix="p"/>`` inside a body (or a frame, a
replicate, the world) copies the body ``b`` of the asset ``<model name="m">``
with its subtree, its names prefixed with ``p`` (see
:mod:`mjcf_model.transforms.composition.attached_parts` for what is copied). Measured on MuJoCo 3.9
and 4.0, the expansion reproduces:

* **Where**: the copy stands where the ``<attach>`` stands, in document order
  among its siblings; the ``childclass`` around it does not reach it.
* **Outside the tree**: copied elements (assets, default classes, tendons,
  actuators, sensors, ...) come after all of the parent's own, in the order of
  the ``<attach>`` elements.
* **Compilers**: each model keeps its own ``<compiler>``: the copy is converted
  into the parent's conventions
  (:func:`mjcf_model.transforms.composition.conventions.in_conventions`) and its
  file paths resolve from the sub-model's folder (``<model file>`` is read from
  the parent's folder, the sub-model's files from its own). A parent
  in degrees that attaches a model in radians is rewritten in radians first
  (MuJoCo's degrees-to-radians is exact to repeat, the other way is not); Euler
  angles in another ``eulerseq`` than the parent's are refused (rewriting them
  in another sequence is exact only to the last digit).
* **Top-level defaults** stay with their model
  (:mod:`mjcf_model.transforms.composition.main_defaults`).
* **Nesting**: a sub-model's own ``<attach>`` elements are expanded first.
* **Keyframes**: the parent's keys are read against the whole model, as
  written. MuJoCo adds one key per key of each attached model: the sub-model's
  values for the copied joints, and the whole model's initial state elsewhere
  (and, where the same ``<model>`` is attached again later, the earlier key's
  values for the copies' joints that the earlier ``<attach>`` did not copy).
  These keys are taken from MuJoCo compiling the original model, so the model
  must compile when a sub-model has keys.
* **Without** ``model`` (MuJoCo 4.0): a body or frame written before the
  ``<attach>`` in the same model is copied, with what refers to it.

Includes are inlined first; asset ``<model>`` elements are removed at the end.

>>> import pathlib, tempfile
>>> from mjcf_model import dumps, load
>>> folder = pathlib.Path(tempfile.mkdtemp())
>>> _ = (folder / "cup.xml").write_text('<mujoco model="cup"><worldbody><body name="cup">'
...                                     '<geom size="0.1"/></body></worldbody></mujoco>')
>>> _ = (folder / "table.xml").write_text('<mujoco><asset><model file="cup.xml"/></asset>'
...     '<worldbody><body name="table"><attach model="cup" body="cup" prefix="a_"/>'
...     '</body></worldbody></mujoco>')
>>> print(dumps(inlined_attachments(load(folder / "table.xml")).worldbody, canonical=True), end="")
<worldbody>
  <body name="table">
    <body name="a_cup">
      <geom size="0.1"/>
    </body>
  </body>
</worldbody>
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

import attrs
import numpy as np

from mjcf_model.bridge.compare import compiled_names
from mjcf_model.bridge.compiling import compiled
from mjcf_model.errors import (
    MjcfCompileError,
    MjcfIncludeCycleError,
    MjcfLookupError,
    MjcfValueError,
)
from mjcf_model.nodes.base import AnyElement, Element, Node, get_attribute, with_attributes
from mjcf_model.nodes.body import Frame
from mjcf_model.nodes.compiler import Compiler
from mjcf_model.nodes.keyframe import Key, Keyframe
from mjcf_model.nodes.root import Mujoco
from mjcf_model.serializers import load
from mjcf_model.serializers.dumping import inlined_includes
from mjcf_model.transforms.composition.attached_parts import attached_part
from mjcf_model.transforms.composition.attaching import attach_in_frame
from mjcf_model.transforms.composition.compiler_settings import compiler_settings
from mjcf_model.transforms.composition.conventions import in_conventions
from mjcf_model.transforms.composition.keyframes import keys_of
from mjcf_model.transforms.naming.generated_names import declarations, model_file_path
from mjcf_model.transforms.naming.renaming import declared_names
from mjcf_model.tree.paths import replaced_at
from mjcf_model.tree.traversal import Path as TreePath
from mjcf_model.tree.traversal import keyed_walk, walk, with_children

if TYPE_CHECKING:
    import mujoco

__all__ = ["inlined_attachments"]

#: The ``MjModel`` arrays of a keyframe, by the ``<key>`` attribute that writes them.
_KEY_ARRAYS = {
    "qpos": "key_qpos",
    "qvel": "key_qvel",
    "act": "key_act",
    "ctrl": "key_ctrl",
    "mpos": "key_mpos",
    "mquat": "key_mquat",
    "plastic": "key_plastic",
}


class _Expansion:
    """One call of :func:`inlined_attachments`: the sub-models read so far, and what is left."""

    def __init__(self) -> None:
        #: The expanded sub-models, by file.
        self.models: dict[Path, Mujoco] = {}
        #: Whether an attached model had keys (MuJoCo then adds keys of its own).
        self.keys_left_out = False

    def expanded(self, model: Mujoco, chain: tuple[Path, ...]) -> Mujoco:
        """``model`` with every ``<attach>`` expanded, its keyframes left as they are."""
        held = [s for s in model.children if getattr(s, "tag", None) == "keyframe"]
        # <size nkey> is held too: attach() would write its blank keys before the held ones
        sizes = {id(s): s for s in model.elements if s.tag == "size" and get_attribute(s, "nkey")}
        plain: dict[int, Node] = {k: with_attributes(s, {"nkey": None}) for k, s in sizes.items()}
        model = attrs.evolve(
            model, children=[plain.get(id(s), s) for s in model.children if s not in held]
        )
        attached = [get_attribute(e, "model") for _, e in walk(model) if e.tag == "attach"]
        children = [self._child(model, str(name), chain) for name in attached if name is not None]
        if any(compiler_settings(child)["angle"] == "radian" for child in children):
            model = _in_radians(model)
        for child in children:
            _check_euler_sequence(child, model)
        while (found := self._first_attach(model)) is not None:
            model = self._expanded_one(model, *found, chain)
        model = _without_model_assets(model)
        restored: dict[int, Node] = {id(plain[k]): size for k, size in sizes.items()}
        sections = [restored.get(id(s), s) for s in model.children]
        return attrs.evolve(model, children=[*sections, *held])

    @staticmethod
    def _first_attach(model: Mujoco) -> tuple[AnyElement, TreePath, int] | None:
        for order, (path, element) in enumerate(walk(model)):
            if element.tag == "attach":
                return element, path, order
        return None

    def _expanded_one(
        self, model: Mujoco, attach: AnyElement, path: TreePath, order: int, chain: tuple[Path, ...]
    ) -> Mujoco:
        body, frame = get_attribute(attach, "body"), get_attribute(attach, "frame")
        prefix = get_attribute(attach, "prefix")
        name = get_attribute(attach, "model")
        if name is None:
            _check_written_before(model, path, order, body, frame)
            child = model
        else:
            child = self._child(model, str(name), chain)
            self.keys_left_out |= bool(keys_of(child))
        part = attached_part(
            child,
            body=None if body is None else str(body),
            frame=None if frame is None else str(frame),
            same_model=name is None,
        )
        marker = _unused_frame_name(model)
        model = replaced_at(model, path, [Frame(name=marker)])
        model = attach_in_frame(model, part, frame=marker, prefix=str(prefix or ""))
        return _without_marker(model, marker)

    def _child(self, model: Mujoco, name: str, chain: tuple[Path, ...]) -> Mujoco:
        """The expanded sub-model of ``model``'s asset ``<model>`` named ``name``."""
        files: dict[str, Path] = {}
        for element, key, _ in keyed_walk(model):
            if key == "asset/model":
                for _, _, declared in declarations(element, key, base_dir=model.base_dir):
                    file = get_attribute(element, "file")
                    files.setdefault(declared, model_file_path(str(file), model.base_dir))
        if name not in files:
            raise MjcfLookupError(
                f"<attach model={name!r}>: no asset <model> has that name; "
                f"the asset models are {sorted(files)}"
            )
        path = files[name]
        if path in chain:
            cycle = " -> ".join(str(p) for p in (*chain, path))
            raise MjcfIncludeCycleError(f"asset <model> files attach each other: {cycle}")
        if path not in self.models:
            self.models[path] = self.expanded(load(path, inline_includes=True), (*chain, path))
        return self.models[path]


def _in_radians(model: Mujoco) -> Mujoco:
    """``model`` with its angles in radians, if they are in degrees.

    MuJoCo turns degrees into radians with a formula that
    :func:`mjcf_model.transforms.composition.conventions.in_conventions` repeats, so
    the radians it writes are the doubles MuJoCo reads; the other way round is not exact. So a model
    that attaches a model in radians is rewritten in radians first.
    """
    if compiler_settings(model)["angle"] != "degree":
        return model
    compilers = [
        (index, with_attributes(section, {"angle": "radian"}))
        for index, section in enumerate(model.children)
        if isinstance(section, Element) and section.tag == "compiler"
    ] or [(0, Compiler(angle="radian"))]
    target = attrs.evolve(model, children=[section for _, section in compilers])
    sections = list(in_conventions(model, target).children)
    for index, section in compilers:
        sections.insert(index, section)
    return attrs.evolve(model, children=sections)


def _check_euler_sequence(child: Mujoco, parent: Mujoco) -> None:
    """Raise where the child's Euler angles would be rewritten in another sequence.

    :func:`mjcf_model.transforms.composition.conventions.in_conventions` rewrites them through a
    quaternion, which may move an angle by one unit in the last place, and then
    MuJoCo's rotation by as much: not the model MuJoCo attaches.
    """
    sequence = compiler_settings(child)["eulerseq"]
    if sequence == compiler_settings(parent)["eulerseq"]:
        return
    if any(get_attribute(e, "euler") is not None for _, e in walk(child)):
        raise MjcfValueError(
            f"cannot expand an <attach> of a model with compiler eulerseq={sequence!r} into one "
            f"with eulerseq={compiler_settings(parent)['eulerseq']!r}: its euler angles would be "
            "rewritten in the other sequence, exactly only to the last digit; write them as "
            "quat (or give both models the same eulerseq) first"
        )


def _check_written_before(
    model: Mujoco, path: TreePath, order: int, body: object, frame: object
) -> None:
    """Raise unless the body or frame an ``<attach>`` without ``model`` copies comes before it."""
    wanted = ("body", body) if body is not None else ("frame", frame)
    if wanted[1] is None:
        raise MjcfValueError("an <attach> without model must name a body or a frame to copy")
    for index, (where, element) in enumerate(walk(model)):
        if (element.tag, get_attribute(element, "name")) == wanted:
            if where == path[: len(where)]:
                raise MjcfValueError(
                    f"<attach {wanted[0]}={wanted[1]!r}> is inside the {wanted[0]} it copies"
                )
            if index < order:
                return
    raise MjcfLookupError(
        f"<attach {wanted[0]}={wanted[1]!r}> without model: no {wanted[0]} of that name is "
        "written before it (MuJoCo copies only what it has read)"
    )


def _unused_frame_name(model: Mujoco) -> str:
    taken = declared_names(model).get("frame", frozenset())
    count = 0
    while f"attach_{count}" in taken:
        count += 1
    return f"attach_{count}"


def _without_marker(model: Mujoco, marker: str) -> Mujoco:
    """``model`` with the frame ``marker`` replaced by its children."""
    for path, element in walk(model):
        if element.tag == "frame" and get_attribute(element, "name") == marker:
            return replaced_at(model, path, element.children)
    raise AssertionError(f"the frame {marker!r} is gone")  # pragma: no cover


def _without_model_assets(model: Mujoco) -> Mujoco:
    """``model`` without asset ``<model>`` elements (and asset sections left empty by that)."""
    sections: list[Node] = []
    for section in model.children:
        if isinstance(section, Element) and section.tag == "asset":
            if not any(e.tag == "model" for e in section.elements):
                sections.append(section)
                continue
            kept = [n for n in section.children if getattr(n, "tag", None) != "model"]
            if any(isinstance(n, Element) for n in kept):
                sections.append(with_children(section, kept))
            continue
        sections.append(section)
    return attrs.evolve(model, children=sections)


def _with_attached_keys(expanded: Mujoco, original: Mujoco) -> Mujoco:
    """``expanded`` with the keys MuJoCo adds for the attached models' keys."""
    reference = compiled(original)
    own = keys_of(expanded)
    names = compiled_names(reference)["key"]
    written = [str(get_attribute(k, "name") or "") for k in own]
    if names[: len(own)] != written:
        raise MjcfValueError(
            f"MuJoCo orders this model's keyframes as {names}, not its own {written} first; "
            "the attached keyframes cannot be written in that order"
        )
    added: list[Node] = []
    for index in range(len(own), reference.nkey):
        values: dict[str, object] = {
            attribute: tuple(float(v) for v in getattr(reference, array)[index])
            for attribute, array in _KEY_ARRAYS.items()
            if hasattr(reference, array) and getattr(reference, array).shape[1]
        }
        time = float(reference.key_time[index])
        added.append(Key(name=names[index] or None, time=time or None, **values))  # type: ignore[arg-type]
    if not added:
        return expanded
    sections = list(expanded.children)
    for index in range(len(sections) - 1, -1, -1):
        section = sections[index]
        if isinstance(section, Element) and section.tag == "keyframe":
            sections[index] = with_children(section, [*section.children, *added])
            break
    else:
        sections.append(Keyframe(children=added))
    result = attrs.evolve(expanded, children=sections)
    _check_keys(result, reference)
    return result


def _check_keys(result: Mujoco, reference: mujoco.MjModel) -> None:
    """Raise unless MuJoCo reads the keys of ``result`` as those of ``reference``.

    MuJoCo 3.9 reads keyframes in a model whose ``<replicate>`` copies joints
    against the model before the copies (and copies the keys), so full keys
    cannot be written there.
    """
    try:
        got = compiled(result)
    except MjcfCompileError as error:
        got, why = None, str(error)
    else:
        arrays = ["key_time", *_KEY_ARRAYS.values()]
        same = got.nkey == reference.nkey and all(
            np.array_equal(getattr(got, a), getattr(reference, a))
            for a in arrays
            if hasattr(reference, a)
        )
        why = "" if same else "they compile to other values"
    if why:
        raise MjcfValueError(
            "cannot write the keyframes MuJoCo adds for the attached models' keys as plain "
            f"keyframes ({why}); this MuJoCo reads keyframes differently where a "
            "<replicate> copies joints: remove the attached models' keyframes first"
        )


def inlined_attachments(model: Mujoco) -> Mujoco:
    """``model`` with every ``<attach>`` replaced by the elements MuJoCo attaches there.

    The result has no ``<attach>``, no asset ``<model>`` and no ``<include>``,
    so every transform and query works on it, and MuJoCo compiles it to the
    model it compiles from ``model`` (the module docstring lists what that
    takes). Sub-model files are found through ``model.base_dir`` (the working
    folder for a model built in code).

    Raises:
        MjcfLookupError: An ``<attach>`` names a model, body or frame that does not exist.
        MjcfIncludeError: Sub-model files attach each other in a cycle, or one is missing.
        MjcfValueError: A construct MuJoCo copies in a way not reproduced here
            (the message names it), or one :func:`mjcf_model.attach` refuses.
        MjcfCompileError: A sub-model has keyframes and ``model`` does not compile.

    Examples:
        >>> from mjcf_model import loads
        >>> model = loads('<mujoco><worldbody><body name="a"><geom size="1"/></body>'
        ...               '<body name="b"><attach body="a" prefix="c_"/></body>'
        ...               '</worldbody></mujoco>')
        >>> [b.name for b in inlined_attachments(model).worldbody.bodies[1].bodies]
        ['c_a']

    """
    original = inlined_includes(model)
    if not any(e.tag in ("attach", "model") for _, e in walk(original)):
        return original
    expansion = _Expansion()
    expanded = expansion.expanded(original, ())
    if expansion.keys_left_out:
        expanded = _with_attached_keys(expanded, original)
    return expanded
