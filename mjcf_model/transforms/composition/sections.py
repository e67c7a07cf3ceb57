"""The top-level sections of a model being composed: which merge, which the parent keeps.

:func:`mjcf_model.attach` adds the child's elements to the parent's section of
the same tag (:data:`LISTS`), keeps the parent's settings (:data:`SETTINGS`,
warning with :class:`~mjcf_model.errors.MjcfDroppedSettingWarning` for each of
the child's that is dropped), and writes the scene's keys as one ``<keyframe>``.

>>> from mjcf_model import loads
>>> parent = loads('<mujoco><option timestep="0.002"/></mujoco>')
>>> child = loads('<mujoco><option timestep="0.01" gravity="0 0 -9.81"/></mujoco>')
>>> for setting in dropped_settings(by_tag(parent)["option"], by_tag(child)["option"]):
...     print(setting)
<option timestep="0.01"> (the parent has "0.002")
<option gravity="0 0 -9.81"> (the parent writes none: MuJoCo's default holds)
"""

from __future__ import annotations

import sys
import warnings
from collections.abc import Collection, Mapping, Sequence
from pathlib import Path

from mjcf_model.errors import Advice, MjcfDroppedSettingWarning, MjcfValueError
from mjcf_model.nodes.base import AnyElement, Element, Node, attribute_items
from mjcf_model.nodes.keyframe import Keyframe
from mjcf_model.nodes.registry import CLASS_BY_KEY
from mjcf_model.nodes.root import Mujoco
from mjcf_model.tree.paths import replaced_at
from mjcf_model.tree.traversal import keyed_walk, walk, with_children
from mjcf_model.values import format_value

__all__ = [
    "LISTS",
    "SETTINGS",
    "by_tag",
    "check_collisions",
    "dropped_settings",
    "inserted",
    "merged_into",
    "warn_dropped",
    "with_keys",
]

#: No names.
_NONE: frozenset[str] = frozenset()
#: Sections whose settings the parent keeps; a parent without one adopts the child's.
#: (Not ``<compiler>``: the child is converted into the parent's conventions.)
SETTINGS = ("option", "size", "statistic", "visual")
#: Sections whose elements are added to the parent's section of the same tag.
LISTS = (
    "extension",
    "custom",
    "asset",
    "deformable",
    "contact",
    "equality",
    "tendon",
    "actuator",
    "sensor",
)


def by_tag(model: Mujoco) -> dict[str, list[AnyElement]]:
    """The model's sections by tag, in order."""
    found: dict[str, list[AnyElement]] = {}
    for section in model.children:
        if isinstance(section, Element):
            found.setdefault(section.tag, []).append(section)
    return found


def check_collisions(declared: dict[str, set[str]], theirs: Mapping[str, Collection[str]]) -> None:
    """Raise when the child's names ``theirs`` meet the parent's ``declared`` ones."""
    if all(declared.get(namespace, _NONE).isdisjoint(names) for namespace, names in theirs.items()):
        return
    clashes = {
        namespace: sorted(set(names) & declared.get(namespace, set()))
        for namespace, names in theirs.items()
    }
    clashes = {namespace: names for namespace, names in clashes.items() if names}
    if clashes:
        listed = "; ".join(
            f"{namespace}: {', '.join(names)}" for namespace, names in clashes.items()
        )
        merged = "key" in clashes
        raise MjcfValueError(
            f"the child declares names the parent already has ({listed})",
            advice=Advice(
                "attach it with a prefix"
                + (" (or keys of one name with keyframes='merged')" if merged else ""),
                "give the part a prefix (FILE:PREFIX)"
                + (" (or keys of one name with --keyframes merged)" if merged else ""),
            ),
        )


def _settings(sections: Sequence[Node]) -> dict[tuple[str, str], str]:
    """Every attribute the sections write, by (element path, attribute); later ones win."""
    found: dict[tuple[str, str], str] = {}
    for section in sections:
        if not isinstance(section, Element):
            continue
        for element, _, ancestors in keyed_walk(section, "mujoco"):
            tags = "><".join([*(a.tag for a in ancestors), element.tag])
            for attribute, value in attribute_items(element):
                found[tags, attribute] = format_value(value)
    return found


def dropped_settings(kept: Sequence[Node], theirs: Sequence[Node]) -> list[str]:
    """The child's settings in ``theirs`` that the parent's ``kept`` sections replace.

    A setting the parent writes with the same text is not dropped; one the
    parent does not write is (MuJoCo's default then holds).
    """
    ours = _settings(kept)
    dropped = []
    for (element, attribute), value in _settings(theirs).items():
        held = ours.get((element, attribute))
        if held == value:
            continue
        why = (
            f'the parent has "{held}"'
            if held is not None
            else "the parent writes none: MuJoCo's default holds"
        )
        dropped.append(f'<{element} {attribute}="{value}"> ({why})')
    return dropped


def warn_dropped(dropped: list[str], prefix: str) -> None:
    """Warn with :class:`MjcfDroppedSettingWarning`, naming each setting in ``dropped``."""
    if dropped:
        child = f"the child attached with prefix {prefix!r}" if prefix else "the child"
        warnings.warn(
            MjcfDroppedSettingWarning(
                f"{child} loses settings the parent's replace: {'; '.join(dropped)}"
            ),
            stacklevel=_outside_the_library(),
        )


def _outside_the_library() -> int:
    """The ``stacklevel`` of the first caller outside this package (attach, attach_all, ...)."""
    package = str(Path(__file__).parents[2])
    frame, level = sys._getframe(1), 1
    while frame.f_back is not None and frame.f_code.co_filename.startswith(package):
        frame, level = frame.f_back, level + 1
    return level


def merged_into(sections: list[Node], tag: str, nodes: list[Node]) -> None:
    """Append ``nodes`` to the last ``tag`` section, or add a new section at the end."""
    for index in range(len(sections) - 1, -1, -1):
        section = sections[index]
        if isinstance(section, Element) and section.tag == tag:
            sections[index] = with_children(section, [*section.children, *nodes])
            return
    sections.append(CLASS_BY_KEY[tag](children=nodes))


def with_keys(sections: list[Node], keys: list[Node]) -> list[Node]:
    """``sections`` with ``keys`` as its one ``<keyframe>`` (where the first one was)."""
    found = [i for i, c in enumerate(sections) if getattr(c, "tag", None) == "keyframe"]
    if not found:
        return [*sections, Keyframe(children=keys)] if keys else sections
    first = sections[found[0]]
    assert isinstance(first, Element)
    kept = [c for i, c in enumerate(sections) if i == found[0] or i not in found]
    kept[found[0]] = with_children(first, keys)
    return kept


def inserted(model: Mujoco, target: AnyElement, nodes: list[Node]) -> Mujoco:
    """``model`` with ``nodes`` appended to the children of ``target`` (found by identity)."""
    path = next(path for path, element in walk(model) if element is target)
    return replaced_at(model, path, [with_children(target, [*target.children, *nodes])])
