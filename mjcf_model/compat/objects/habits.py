"""Like robosuite's habits, as small functions on nodes, for the object classes.

The object classes must produce the very XML robosuite produces, so the habits
that decide it live here, each a function from nodes to nodes. Where robosuite's
objects call a function of ``mjcf_utils``, the compatible one
(``mjcf_model.compat.mjcf_utils``) is the one implementation, called here:

* numbers as robosuite writes them: ``array_to_string`` of
  :mod:`~mjcf_model.compat.mjcf_utils.text` (``"{}".format`` of each value, so numpy
  floats give ``"0.0"``) and :func:`value_text` (``convert_to_string``'s rule,
  more tolerant);
* elements with robosuite's attribute order (the ``rs_*`` builders, mirroring
  ``new_geom``, ``new_site``... with the node builders of
  :mod:`~mjcf_model.compat.mjcf_utils.builders`), as generic elements holding that
  exact text;
* prefixing that skips values already starting with the prefix
  (:func:`~mjcf_model.compat.objects.naming.robosuite_prefixed`);
* scaling of only the attributes robosuite scales (:func:`robosuite_scaled`,
  with the rules of :mod:`~mjcf_model.compat.mjcf_utils.scaling`);
* default classes written inline (:func:`inline_defaults`) and the geom split
  of XML objects (:func:`split_geoms`) in :mod:`mjcf_model.compat.objects.xml`.

>>> print(rs_geom("g", "box", [0.5, 0, 1]).attributes["size"], "|", value_text(np.float32(0.5)))
0.5 0 1 | 0.5
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping, Sequence
from typing import Any

import numpy as np
import numpy.typing as npt

from mjcf_model.compat.mjcf_utils import constants as utils_constants
from mjcf_model.compat.mjcf_utils.builders import (
    body_node,
    element_node,
    geom_node,
    joint_node,
    site_node,
)
from mjcf_model.compat.mjcf_utils.etree_sync import attribute
from mjcf_model.compat.mjcf_utils.scaling import (
    scaled_body,
    scaled_geom,
    scaled_joint,
    scaled_mesh,
    scaled_site,
)
from mjcf_model.compat.mjcf_utils.text import array_to_string, text_of, three_factors
from mjcf_model.errors import MjcfValueError
from mjcf_model.nodes.base import AnyElement, GenericElement, Node, TypedElement
from mjcf_model.transforms.naming.repeated import with_texts as checked_texts
from mjcf_model.transforms.scaling.scaled import _factors as checked_factors
from mjcf_model.tree.traversal import with_children

__all__ = [
    "OBJECT_COLLISION_COLOR",
    "attribute",
    "robosuite_scaled",
    "rs_body",
    "rs_element",
    "rs_geom",
    "rs_joint",
    "rs_site",
    "scale_factors",
    "value_text",
    "with_texts",
]

#: robosuite's ``OBJECT_COLLISION_COLOR``, as it writes it (``"0.5 0 0 1"``).
OBJECT_COLLISION_COLOR = array_to_string(utils_constants.OBJECT_COLLISION_COLOR)

#: The rule ``scale_mjcf_model`` applies to each tag it scales; robosuite's objects
#: pass ``scale_slide_joints=False``, so a joint only moves.
_SCALING_RULES: Mapping[str, Callable[[Node, Any], Node]] = {
    "geom": scaled_geom,
    "site": scaled_site,
    "body": scaled_body,
    "joint": lambda node, factors: scaled_joint(node, factors, scale_slide_joints=False),
    "mesh": scaled_mesh,
}


def value_text(value: Any) -> str:
    """Like robosuite's ``convert_to_string``, also accepting numpy scalars (robosuite raises).

    :func:`~mjcf_model.compat.mjcf_utils.text.text_of` without exact types:
    lists, tuples and arrays (subclasses too) go through ``array_to_string``;
    numbers and booleans (numpy's too) are ``str(x).lower()``; text is kept.
    The compatible ``convert_to_string`` keeps robosuite's exact type checks.

    Raises:
        MjcfValueError: a value that is none of these (a dict, ``None``...).

    Example:
        >>> value_text(True), value_text(1e-8), value_text(np.float64(0.5)), value_text([True])
        ('true', '1e-08', '0.5', 'True')

    """
    if type(value) is str:  # most values are text already
        return value
    text = text_of(value, exact=False)
    if text is None:
        raise MjcfValueError(f"unsupported attribute value type: got {type(value)} ({value!r})")
    return text


def with_texts(element: AnyElement, changes: Mapping[str, str | None]) -> AnyElement:
    """``element`` with attributes set to text (``None`` removes); positions kept like ``set``.

    Example:
        >>> geom = GenericElement(tag="geom", attributes={"a": "1", "b": "2"})
        >>> dict(with_texts(geom, {"a": "3", "c": "4", "b": None}).attributes)
        {'a': '3', 'c': '4'}

    """
    return checked_texts(element, changes)


def rs_element(
    tag: str,
    extra: Mapping[str, Any],
    fixed: Sequence[tuple[str, Any]] = (),
    name: str | None = None,
) -> GenericElement:
    """Like robosuite's ``new_element`` after its wrapper placed the named parameters.

    The attributes come in robosuite's order: ``extra`` (the ``**kwargs``, in
    order), then ``fixed`` (the named parameters, in the wrapper's order), then
    ``name``; ``None`` values are dropped; values become text with
    :func:`value_text`.

    Example:
        >>> rs_element("body", {"quat": None, "mass": 0.5}, [("pos", (0, 0, 1))], "b").attributes
        AttributeMap({'mass': '0.5', 'pos': '0 0 1', 'name': 'b'})

    """
    items = {**extra, **dict(fixed), "name": name}
    return element_node(tag, items.items(), value_text)


def rs_geom(
    name: str | None,
    type: str | None,
    size: Any,
    pos: Any = (0, 0, 0),
    group: Any = 0,
    **extra: Any,
) -> GenericElement:
    """Like robosuite's ``new_geom``: extra attributes, then type, size, pos, group, name.

    Example:
        >>> dict(rs_geom("g", "box", [0.1, 0.1, 0.1]).attributes)  # doctest: +NORMALIZE_WHITESPACE
        {'type': 'box', 'size': '0.1 0.1 0.1', 'pos': '0 0 0', 'group': '0',
         'name': 'g'}

    """
    return geom_node(name, type, size, pos, group, extra, value_text)


def rs_site(
    name: str | None = None,
    rgba: Any = (1, 0, 0, 1),
    pos: Any = (0, 0, 0),
    size: Any = (0.005,),
    **extra: Any,
) -> GenericElement:
    """Like robosuite's ``new_site``: extra attributes, then pos, size, rgba, name.

    Example:
        >>> rs_site("s").attributes
        AttributeMap({'pos': '0 0 0', 'size': '0.005', 'rgba': '1 0 0 1', 'name': 's'})

    """
    return site_node(name, rgba, pos, size, extra, value_text)


def rs_joint(name: str | None = None, **extra: Any) -> GenericElement:
    """Like robosuite's ``new_joint``: the attributes, then name.

    Example:
        >>> rs_joint("j", type="free", damping="0.0005").attributes
        AttributeMap({'type': 'free', 'damping': '0.0005', 'name': 'j'})

    """
    return joint_node(name, extra, value_text)


def rs_body(name: str | None = None, pos: Any = (0, 0, 0), **extra: Any) -> GenericElement:
    """Like robosuite's ``new_body``: the attributes, then pos, then name.

    Example:
        >>> rs_body("main").attributes
        AttributeMap({'pos': '0 0 0', 'name': 'main'})

    """
    return body_node(name, pos, extra, value_text)


def scale_factors(scale: Any) -> npt.NDArray[Any]:
    """Like robosuite's ``normalize_scale_array``: one number or three, as an array of three.

    Raises:
        MjcfValueError: anything but one or three numbers.

    Example:
        >>> scale_factors(2), scale_factors([1, 2, 3])
        (array([2, 2, 2]), array([1, 2, 3]))

    """
    factors = three_factors(scale)
    if factors is None:
        raise MjcfValueError(f"Scale must be a scalar or a 3-element array, found {scale!r}")
    return factors


def robosuite_scaled(
    node: AnyElement, scale: Any, tags: Iterable[str], *, include_root: bool = False
) -> AnyElement:
    """Scale what robosuite's objects scale (``scale_mjcf_model``), written as robosuite writes it.

    Each element whose tag is in ``tags`` (``node`` itself only with
    ``include_root``) gets the rule of the compatible ``scale_mjcf_model``
    (:mod:`~mjcf_model.compat.mjcf_utils.scaling`): geom and site ``pos`` and
    ``size`` (sizes by their count of values), body and joint ``pos``, and
    mesh ``scale`` (written as the factors when the mesh has none). Every
    other length stays, as in robosuite (slide joint ranges, margins, the root
    body's own position). Values are written with numpy's float text,
    ``"0.0 0.0 0.0"``, as robosuite writes them, even for a factor of 1.
    Unlike robosuite, the factors must be finite and positive, as for
    :func:`mjcf_model.scaled`.

    Raises:
        MjcfValueError: the factor is not one or three positive numbers, or an
            element cannot be scaled (a size of more than three values, text
            that is not numbers).

    Example:
        >>> geom = GenericElement(tag="geom", attributes={"pos": "0 0 0", "size": "0.1 0.2 0.3"})
        >>> body = GenericElement(tag="body", attributes={"pos": "0 0 1"}, children=[geom])
        >>> new = robosuite_scaled(body, [1, 2, 3], {"geom", "body"})
        >>> new.attributes["pos"], dict(new.children[0].attributes)
        ('0 0 1', {'pos': '0.0 0.0 0.0', 'size': '0.1 0.4 0.8999999999999999'})

    """
    chosen = frozenset(tags)
    factors = np.array(checked_factors(scale_factors(scale).astype(float)))

    def visit(element: AnyElement, is_root: bool) -> AnyElement:
        children: list[Node] = [
            visit(child, False) if isinstance(child, (TypedElement, GenericElement)) else child
            for child in element.children
        ]
        element = with_children(element, children)
        rule = _SCALING_RULES.get(element.tag)
        if rule is None or element.tag not in chosen or (is_root and not include_root):
            return element
        try:
            new = rule(element, factors)
        except ValueError as error:
            raise MjcfValueError(f"<{element.tag}> cannot be scaled: {error}") from error
        assert isinstance(new, (TypedElement, GenericElement))
        return new

    return visit(node, True)
