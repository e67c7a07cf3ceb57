"""The dict form's converter: the caller may own one, and the default one sees later classes."""

from __future__ import annotations

from typing import Any, ClassVar

import cattrs

from mjcf_model import Geom, Site
from mjcf_model.nodes.base import TypedElement
from mjcf_model.nodes.declaring import node
from mjcf_model.nodes.fields import vec3
from mjcf_model.serializers import from_dict, make_converter, to_dict
from mjcf_model.serializers.dicts import NodeConverter, default_converter


def test_an_owned_converter_changes_only_its_own_conversions() -> None:
    """Hooks registered on a converter from ``make_converter`` reach no other caller."""
    mine = make_converter()
    mine.register_unstructure_hook(str, str.upper)
    mine.register_structure_hook(str, lambda value, _: str(value).lower())
    site = Site(name="tip", pos=(0, 0, 1))
    assert to_dict(site, converter=mine) == {"name": "TIP", "pos": [0.0, 0.0, 1.0], "_node": "Site"}
    assert to_dict(site) == {"name": "tip", "pos": [0.0, 0.0, 1.0], "_node": "Site"}
    assert from_dict({"_node": "Site", "name": "TIP"}, converter=mine) == Site(name="tip")
    assert from_dict({"_node": "Site", "name": "TIP"}) == Site(name="TIP")
    assert make_converter() is not make_converter()
    assert isinstance(mine, cattrs.Converter) and isinstance(default_converter(), NodeConverter)


def test_the_default_converter_knows_classes_declared_after_its_first_use() -> None:
    """A node class declared after the first ``to_dict`` converts both ways too."""
    geom = Geom(name="g", size=[0.1])
    assert from_dict(to_dict(geom)) == geom
    before = default_converter()

    @node
    class LaterThing(TypedElement):
        tag: ClassVar[str] = "laterthing"
        size: tuple[float, ...] | None = vec3()

    thing = LaterThing(size=[1, 2, 3])
    data: dict[str, Any] = to_dict(thing)
    assert data == {"size": [1.0, 2.0, 3.0], "_node": "LaterThing"}
    assert from_dict(data) == thing
    assert default_converter() is not before
    assert from_dict(to_dict(geom)) == geom
