"""Prefixing one tree many times: where a prefix goes is found once, then written for each prefix.

Composing N copies of one model (:func:`mjcf_model.attach_all`) and making N
robosuite objects from one file prefix the same tree again and again, with
another prefix each time. Which attributes change, and where the prefix goes
in them, does not depend on the prefix: :meth:`PrefixPlan.traced` prefixes the
tree once with a marker character (:data:`MARK`) and records the attributes
that gained it; :meth:`PrefixPlan.applied` writes a prefix in their place,
rebuilding only the elements on those paths and sharing every other subtree,
as the prefixing it traced does. A plan is checked when it is traced: applied
with the marker it gives back the traced result exactly.

>>> from mjcf_model import Body, Geom, prefixed
>>> body = Body(name="cup", children=[Geom(name="wall", size=[0.1]), Geom(size=[0.2])])
>>> plan = PrefixPlan.traced(body, prefixed)
>>> plan.applied(body, "a_") == prefixed(body, "a_")
True
>>> plan.applied(body, "b_").children[1] is body.children[1]
True
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TypeVar

from mjcf_model.nodes.base import (
    AnyElement,
    AttributeMap,
    Comment,
    Element,
    GenericElement,
    attribute_items,
    build_node,
    field_table,
    with_attributes,
)
from mjcf_model.values import Value, check_text

__all__ = ["MARK", "PrefixPlan", "Prefixer", "RepeatedPrefixing"]

#: The marker a plan is traced with: a private-use character, legal in XML text and
#: in no name people write (a tree whose changed attributes hold it has no plan).
MARK = "\ue000"

#: How deep a plan follows a tree; deeper trees are prefixed the ordinary way.
_DEPTH = 200

_E = TypeVar("_E", bound=Element)

#: Prefixing: the tree and the prefix in, the prefixed tree out.
Prefixer = Callable[[AnyElement, str], AnyElement]

#: One element of a plan: its attribute changes (the attribute, its text with
#: :data:`MARK` for the prefix, and the name alone when the text is one whole name),
#: then the steps of the children that change, by index.
_Step = tuple[tuple[tuple[str, str, str | None], ...], tuple[tuple[int, "_Step"], ...]]


class _Untraceable(Exception):
    """The traced prefixing did something a plan cannot repeat."""


class PrefixPlan:
    """Where a prefixing of one tree writes its prefix, to write any other prefix there."""

    __slots__ = ("_root",)

    def __init__(self, root: _Step) -> None:
        #: The step of the tree's root.
        self._root = root

    @classmethod
    def traced(
        cls,
        node: AnyElement,
        prefixer: Prefixer,
        *,
        by_name: bool = False,
    ) -> PrefixPlan | None:
        """The plan of ``prefixer(node, prefix)``, or ``None`` where one cannot stand for it.

        Args:
            node: The tree prefixed.
            prefixer: Prefixing, a pure function of the tree and the prefix that
                only puts the prefix into attribute text (:func:`mjcf_model.prefixed`).
            by_name: Require every prefix to stand before a whole name (at the
                start of the text, or of a space-separated word), so that
                :meth:`applied` can leave names out by their name (``keep``).

        ``None`` when the prefixing changes anything but attribute text, puts the
        prefix where ``by_name`` does not allow it, meets text that already holds
        :data:`MARK`, or the tree is deeper than a plan follows.

        Examples:
            >>> from mjcf_model import Body, prefixed
            >>> PrefixPlan.traced(Body(name="b"), prefixed) is not None
            True

        """
        marked = prefixer(node, MARK)
        try:
            root = _traced(node, marked, by_name, 0)
        except _Untraceable:
            return None
        plan = cls(root)
        if plan.applied(node, MARK) != marked:
            return None
        return plan

    def applied(self, node: _E, prefix: str, keep: Callable[[str], bool] | None = None) -> _E:
        """``node`` (the traced tree, or one its prefixing treats alike) with ``prefix`` written.

        Args:
            node: The tree.
            prefix: The prefix.
            keep: Names to leave as they are (only for a plan traced ``by_name``).

        Examples:
            >>> from mjcf_model import Body, Geom, prefixed
            >>> body = Body(name="b", children=[Geom(name="p_g")])
            >>> plan = PrefixPlan.traced(body, prefixed, by_name=True)
            >>> new = plan.applied(body, "p_", keep=lambda name: name.startswith("p_"))
            >>> new.name, new.children[0].name
            ('p_b', 'p_g')

        """
        check_text(prefix, "prefix")
        return _applied(node, self._root, prefix, keep)


class RepeatedPrefixing:
    """One tree prefixed again and again: the ordinary way once, then through its plan.

    The first prefix is written by ``prefixer`` itself; at the second the plan
    is traced (:meth:`PrefixPlan.traced`), and from then on only written, so a
    tree prefixed once costs no more than before and N copies cost one tracing.

    Args:
        model: The tree.
        prefixer: Its prefixing, as for :meth:`PrefixPlan.traced`.

    Examples:
        >>> from mjcf_model import Body, prefixed
        >>> copies = RepeatedPrefixing(Body(name="cup"), prefixed)
        >>> [copies.prefixed(f"c{i}_").name for i in range(3)]
        ['c0_cup', 'c1_cup', 'c2_cup']

    """

    def __init__(self, model: AnyElement, prefixer: Prefixer) -> None:
        #: The tree.
        self.model = model
        self._prefixer = prefixer
        self._copies = 0
        self._plan: PrefixPlan | None = None

    def prefixed(self, prefix: str) -> AnyElement:
        """The tree with ``prefix`` written, as ``prefixer`` writes it.

        Examples:
            >>> from mjcf_model import Body, prefixed
            >>> RepeatedPrefixing(Body(name="cup"), prefixed).prefixed("a_").name
            'a_cup'

        """
        self._copies += 1
        if self._copies == 2:
            self._plan = PrefixPlan.traced(self.model, self._prefixer)
        if self._plan is not None:
            return self._plan.applied(self.model, prefix)
        return self._prefixer(self.model, prefix)


def _traced(before: AnyElement, after: AnyElement, by_name: bool, depth: int) -> _Step:
    """The step that turns ``before`` into ``after`` (the same tree prefixed with the marker)."""
    if depth > _DEPTH or type(before) is not type(after) or before.tag != after.tag:
        raise _Untraceable
    if before.text != after.text or len(before.children) != len(after.children):
        raise _Untraceable
    old: dict[str, Value] = dict(attribute_items(before))
    new: dict[str, Value] = dict(attribute_items(after))
    if not old.keys() <= new.keys():
        raise _Untraceable
    changes: list[tuple[str, str, str | None]] = []
    for name, value in new.items():
        was = old.get(name)
        if was == value:
            continue
        if not isinstance(value, str) or MARK not in value or (by_name and not _by_name(value)):
            raise _Untraceable
        if isinstance(was, str) and MARK in was:
            raise _Untraceable
        whole = value.startswith(MARK) and value.count(MARK) == 1
        changes.append((name, value, value[len(MARK) :] if whole else None))
    steps: list[tuple[int, _Step]] = []
    for index, (child, marked) in enumerate(zip(before.children, after.children, strict=True)):
        if child is marked:
            continue
        if isinstance(child, Comment) or isinstance(marked, Comment):
            if child != marked:
                raise _Untraceable
            continue
        assert isinstance(child, Element)
        assert isinstance(marked, Element)
        step = _traced(child, marked, by_name, depth + 1)
        if step[0] or step[1]:
            steps.append((index, step))
    return tuple(changes), tuple(steps)


def _by_name(value: str) -> bool:
    """Whether every marker in ``value`` stands before a whole name."""
    if value.count(MARK) == 1:
        return value.startswith(MARK)
    return all(word.startswith(MARK) or MARK not in word for word in value.split(" "))


def _applied(element: _E, step: _Step, prefix: str, keep: Callable[[str], bool] | None) -> _E:
    changes, steps = step
    values: dict[str, str] = {}
    for name, marked, whole in changes:
        if whole is not None:  # one name, the common case
            if keep is None or not keep(whole):
                values[name] = prefix + whole
        elif keep is None:
            values[name] = marked.replace(MARK, prefix)
        elif (text := _kept_text(marked, prefix, keep)) is not None:
            values[name] = text
    fields: dict[str, object] = {}
    if values:  # set with the children below, in one build
        if isinstance(element, GenericElement):
            # the names were checked when the plan was traced, the prefix by applied()
            texts = element.attributes
            data = {key: texts[key] for key in texts}
            data.update(values)
            fields["attributes"] = AttributeMap.unchecked(data)
        else:
            table = field_table(type(element))
            if all(name in table for name in values):  # typed fields (names are)
                fields.update((table[name], text) for name, text in values.items())
            else:
                element = with_attributes(element, values)
    if steps:
        children = list(element.children)
        for index, inner in steps:
            child = children[index]
            assert isinstance(child, Element)
            children[index] = _applied(child, inner, prefix, keep)
        fields["children"] = tuple(children)
    return build_node(type(element), fields, element) if fields else element


def _kept_text(marked: str, prefix: str, keep: Callable[[str], bool]) -> str | None:
    """``marked`` with ``prefix`` before each name ``keep`` refuses; ``None``: it keeps them all."""
    words = [marked] if marked.count(MARK) == 1 else marked.split(" ")
    written = False
    for index, word in enumerate(words):
        if word.startswith(MARK):
            name = word[len(MARK) :]
            if keep(name):
                words[index] = name
            else:
                words[index] = prefix + name
                written = True
    return " ".join(words) if written else None
