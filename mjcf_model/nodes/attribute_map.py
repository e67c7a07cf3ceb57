"""The attributes an element does not model: an immutable, ordered, hashable mapping of text.

>>> m = AttributeMap({"b": "1", "a": "2"})
>>> list(m), m == AttributeMap({"a": "2", "b": "1"})
(['b', 'a'], True)
"""

from __future__ import annotations

from collections.abc import ItemsView, Iterable, Iterator, KeysView, Mapping, ValuesView
from typing import TypeVar, overload

from mjcf_model.errors import MjcfValueError
from mjcf_model.values import check_name, check_text

__all__ = ["EMPTY_ATTRIBUTES", "AttributeMap", "to_attribute_map"]

_T = TypeVar("_T")


class AttributeMap(Mapping[str, str]):
    """An immutable, ordered, hashable mapping of XML attribute names to text.

    Equality ignores order, like XML itself.

    Examples:
        >>> m = AttributeMap({"b": "1", "a": "2"})
        >>> list(m), m == AttributeMap({"a": "2", "b": "1"})
        (['b', 'a'], True)

    """

    __slots__ = ("_data", "_hash")

    def __init__(self, items: Mapping[str, str] | Iterable[tuple[str, str]] = ()) -> None:
        data = dict(items)
        for key, value in data.items():
            if not isinstance(key, str) or not isinstance(value, str):
                raise MjcfValueError(
                    f"attribute names and values must be text, found {key!r}={value!r}"
                )
            check_name(key, "attribute name")
            check_text(value, f"attribute {key!r}")
        self._data = data
        self._hash: int | None = None

    @classmethod
    def unchecked(cls, data: dict[str, str]) -> AttributeMap:
        r"""Wrap ``data`` without checking that XML can carry it.

        Only for the robosuite layer, whose ElementTree elements take any text
        (robosuite's ``new_element(name="\x1f")`` works); such a map is converted
        to ElementTree at once and never written by :mod:`mjcf_model.serializers`.
        """
        made = cls.__new__(cls)
        made._data = data
        made._hash = None
        return made

    def __getitem__(self, key: str) -> str:
        return self._data[key]

    def __iter__(self) -> Iterator[str]:
        return iter(self._data)

    def __len__(self) -> int:
        return len(self._data)

    # The Mapping mixins work item by item in Python; these pass through to the dict.
    def __contains__(self, key: object) -> bool:
        return key in self._data

    @overload
    def get(self, key: str, /) -> str | None: ...
    @overload
    def get(self, key: str, /, default: str | _T) -> str | _T: ...
    def get(self, key: str, /, default: object = None) -> object:
        """The text of ``key``, or ``default`` when the element does not write it."""
        return self._data.get(key, default)

    def keys(self) -> KeysView[str]:
        """The attribute names, in order."""
        return self._data.keys()

    def values(self) -> ValuesView[str]:
        """The attribute texts, in order."""
        return self._data.values()

    def items(self) -> ItemsView[str, str]:
        """The ``(name, text)`` pairs, in order."""
        return self._data.items()

    def __hash__(self) -> int:
        if self._hash is None:
            self._hash = hash(frozenset(self._data.items()))
        return self._hash

    def __eq__(self, other: object) -> bool:
        if isinstance(other, AttributeMap):
            return self._data == other._data
        if isinstance(other, Mapping):
            return self._data == dict(other)
        return NotImplemented

    def __repr__(self) -> str:
        return f"AttributeMap({self._data!r})"

    def replaced(self, changes: Mapping[str, str | None]) -> AttributeMap:
        """Return a copy with ``changes`` applied; ``None`` removes a key.

        Only the new names and text are checked (the others were when this map was made).

        Examples:
            >>> AttributeMap({"a": "1"}).replaced({"a": None, "b": "2"})
            AttributeMap({'b': '2'})

        """
        data = dict(self._data)
        for key, value in changes.items():
            if value is None:
                data.pop(key, None)
                continue
            if key not in data:
                check_name(key, "attribute name")
            if not isinstance(value, str):
                raise MjcfValueError(f"attribute values must be text, found {key!r}={value!r}")
            data[key] = check_text(value, f"attribute {key!r}")
        return AttributeMap.unchecked(data)


#: The empty map every element without such attributes shares.
EMPTY_ATTRIBUTES = AttributeMap()


def to_attribute_map(value: Mapping[str, str] | Iterable[tuple[str, str]] | None) -> AttributeMap:
    """Converter: any mapping or pair sequence becomes an :class:`AttributeMap`.

    Examples:
        >>> to_attribute_map({"x": "1"})
        AttributeMap({'x': '1'})

    """
    if isinstance(value, AttributeMap):
        return value
    if not value:
        return EMPTY_ATTRIBUTES
    return AttributeMap(value)
