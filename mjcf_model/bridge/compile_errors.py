r"""Where the element MuJoCo rejects stands in the user's files.

:func:`~mjcf_model.bridge.compiling.compiled` hands MuJoCo text it wrote itself, so
the line MuJoCo names is a line of that text, which the user has never seen.
:func:`compile_error` reads that text back, finds the element standing on that
line, and follows it to the element of the user's model: its element path, and
the file and line it was read from (a part attached from another folder: the
part's own file). Nothing here runs unless MuJoCo rejects a model.

>>> from mjcf_model import loads
>>> from mjcf_model.bridge.compiling import compiled
>>> model = loads('<mujoco>\n<worldbody>\n<geom class="x" size="1"/>\n</worldbody>\n</mujoco>',
...               filename="arm.xml")
>>> try:
...     compiled(model)
... except MjcfCompileError as error:
...     print(error.file, error.line, error.path)
...     print(error.detail)
arm.xml 3 /mujoco/worldbody/geom
MuJoCo rejects the model: XML Error: unknown default class name 'x'
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import attrs

from mjcf_model.errors import MjcfCompileError, MjcfError
from mjcf_model.nodes.base import AnyElement, attribute_text
from mjcf_model.nodes.root import Mujoco
from mjcf_model.serializers import dumps, loads
from mjcf_model.serializers.layout import Layout, SourceText, layout_of
from mjcf_model.serializers.locations import element_at
from mjcf_model.tree.traversal import Path, keyed_walk, walk
from mjcf_model.values.encoding import encoded, for_mujoco

if TYPE_CHECKING:
    from mjcf_model.serializers.bundling import Bundle

__all__ = ["Complaint", "compile_error"]


@attrs.frozen
class Complaint:
    r"""MuJoCo's message, split into what it says and the element it names.

    Examples:
        >>> Complaint.parse("XML Error: bad\nElement 'geom', line 4\n")
        Complaint(what='XML Error: bad', line=4, tag='geom', name=None, element="Element 'geom'")

    """

    #: What MuJoCo says is wrong, without the line naming the element.
    what: str
    #: The line of the element in the text MuJoCo was given, ``None`` when it names none.
    line: int | None
    #: The element's tag, when MuJoCo names it (its XML errors do).
    tag: str | None
    #: The element's name (``""``: it has none), when MuJoCo names it (its compile errors do).
    name: str | None
    #: How MuJoCo names the element, its line left out.
    element: str

    @classmethod
    def parse(cls, message: str) -> Complaint:
        r"""Split MuJoCo's ``message``.

        Examples:
            >>> Complaint.parse("Error: no\nElement name 'j', id 0, line 7").name
            'j'
            >>> Complaint.parse("Error: no mass").line is None
            True
            >>> Complaint.parse("Error: bad key\nElement name '', id 0").element
            "Element name '', id 0"

        """
        message = message.strip()
        cut = message.rfind("\nElement ")
        if cut < 0:
            return cls(what=message, line=None, tag=None, name=None, element="")
        last = message[cut + 1 :].strip()
        head, _, line = last.rpartition(", line ")
        if not (head and line.isdigit()):
            head, line = last, ""
        name = tag = None
        if head.startswith("Element name '"):
            name, _, number = head[len("Element name '") :].rpartition("', id ")
            if not number.isdigit():
                cut = -1
        elif head.startswith("Element '") and head.endswith("'") and len(head) > 10:
            tag = head[len("Element '") : -1]
        else:
            cut = -1
        if cut < 0:  # no element named as MuJoCo names one: its words are the whole message
            return cls(what=message, line=None, tag=None, name=None, element="")
        return cls(
            what=message[:cut].strip(),
            line=int(line) if line else None,
            tag=tag,
            name=name,
            element=head,
        )


def compile_error(message: str, model: Mujoco, bundle: Bundle, text: str) -> MjcfCompileError:
    r"""The error for MuJoCo's ``message`` about ``text``, located in the user's files.

    Args:
        message: What MuJoCo raised.
        model: The model as the user gave it.
        bundle: The bundle written from it (includes read in, file paths renamed).
        text: The text written from ``bundle.model`` and given to MuJoCo.

    Examples:
        >>> from mjcf_model import Geom, Mujoco, Worldbody
        >>> from mjcf_model.serializers.bundling import bundled
        >>> from mjcf_model import dumps
        >>> model = Mujoco(children=[Worldbody(children=[Geom(), Geom(dclass="x", size=[1])])])
        >>> bundle = bundled(model)
        >>> message = "XML Error: unknown default class name 'x'\nElement 'geom', line 4"
        >>> error = compile_error(message, model, bundle, dumps(bundle.model))
        >>> error.file, error.line, error.path
        (None, None, '/mujoco/worldbody/geom[2]')

    """
    complaint = Complaint.parse(message)
    if complaint.line is None:
        named = f" ({complaint.element})" if complaint.element else ""
        return MjcfCompileError(
            f"MuJoCo rejects the model (MuJoCo names no line): {complaint.what}{named}",
            file=_main_file(model),
        )
    found = _standing_on(text, complaint)
    if len(found) > 1:  # several on that line: ask again, one element per line
        found = _standing_on_canonical(bundle, complaint)
    located = _in_model(bundle.model, found[0]) if len(found) == 1 else None
    if located is None:
        return MjcfCompileError(
            f"MuJoCo rejects the model: {complaint.what} ({complaint.element}, line "
            f"{complaint.line} of the text mjcf-model wrote for MuJoCo, not of your file)",
            file=_main_file(model),
        )
    element, path = located
    file, line = _source_of(element, model)
    return MjcfCompileError(
        f"MuJoCo rejects the model: {complaint.what}", file=file, line=line, path=path
    )


def _main_file(model: Mujoco) -> str | None:
    layout = layout_of(model)
    return layout.origin.filename if layout is not None else None


def _standing_on(text: str, complaint: Complaint) -> list[tuple[Path, AnyElement]]:
    """The elements of ``text`` starting on the line MuJoCo names, and named as it names them."""
    data = encoded(text)
    if complaint.line is None or complaint.line < 1:  # an included file's line is 0
        return []
    begin = 0
    for _ in range(complaint.line - 1):
        begin = data.find(b"\n", begin) + 1
        if begin == 0:
            return []
    end = data.find(b"\n", begin)
    end = len(data) if end < 0 else end
    try:
        written = loads(data)
    except MjcfError:
        return []
    found = []
    for path, element in walk(written):
        layout = layout_of(element)
        if layout is None or not begin <= layout.begin <= end:
            continue
        if complaint.tag is not None and element.tag != complaint.tag:
            continue
        if complaint.name is not None and (attribute_text(element, "name") or "") != complaint.name:
            continue
        found.append((path, element))
    return found


def _standing_on_canonical(bundle: Bundle, complaint: Complaint) -> list[tuple[Path, AnyElement]]:
    """:func:`_standing_on` for the canonical text, if MuJoCo says the same of it."""
    import mujoco

    canonical = dumps(bundle.model, canonical=True)
    try:
        mujoco.MjModel.from_xml_string(for_mujoco(canonical), bundle.files)
    except ValueError as error:
        again = Complaint.parse(str(error))
        if again.what == complaint.what and again.line is not None:
            return _standing_on(canonical, again)
    return []


def _in_model(model: Mujoco, written: tuple[Path, AnyElement]) -> tuple[AnyElement, str] | None:
    """The element of ``model`` at the index path of ``written``, and its element path."""
    path, element = written
    found = element_at(model, path)
    return found if found is not None and found[0].tag == element.tag else None


def _source_of(element: AnyElement, model: Mujoco) -> tuple[str | None, int | None]:
    """The file and line ``element`` was read from (``None``: built in code)."""
    layout = layout_of(element)
    if layout is None:
        return None, None
    if _includes(model) and _read_from_written(layout.origin, model):
        # compiled() read the model's includes in from the text it wrote of the model
        layout = _user_layout(layout, model)
        if layout is None:
            return None, None
    return layout.origin.filename, layout.origin.line(layout.begin)


def _includes(model: Mujoco) -> bool:
    return any(key == "include" for _, key, _ in keyed_walk(model))


def _read_from_written(origin: SourceText, model: Mujoco) -> bool:

    return origin.slice(0, 1 << 62) == dumps(model)


def _user_layout(layout: Layout, model: Mujoco) -> Layout | None:
    """The layout of the element of ``model`` written at ``layout`` in the model's text."""
    written = loads(dumps(model))
    for path, element in walk(written):
        found = layout_of(element)
        if found is not None and found.begin == layout.begin:
            located = _in_model(model, (path, element))
            return layout_of(located[0]) if located is not None else None
    return None
