"""The one cache helper, and the caches built on it staying bounded under hostile input."""

from __future__ import annotations

from mjcf_model.caching import BoundedCache
from mjcf_model.serializers import loads, open_element, to_dict
from mjcf_model.tree import traversal
from mjcf_model.tree.traversal import map_elements


def test_a_full_cache_empties_before_it_takes_more() -> None:
    """It never holds more than ``limit`` answers, and what it gives back is what it took."""
    cache: BoundedCache[int, str] = BoundedCache(3)
    for number in range(10):
        assert cache.remember(number, str(number)) == str(number)
        assert len(cache) <= 3 and cache[number] == str(number)
    assert cache == {9: "9"}


def test_many_distinct_tags_leave_every_cache_bounded() -> None:
    """A file of 5,000 made-up tags is read, walked and converted; no cache grows past its bound."""
    tags = "".join(f"<made{number}/>" for number in range(5000))
    model = loads(f"<mujoco><worldbody>{tags}</worldbody></mujoco>")
    assert map_elements(lambda element, _key, _ancestors: element, model) is model
    assert len(to_dict(model)["children"][0]["children"]) == 5000
    assert len(open_element.STEPS) <= open_element.STEPS.limit
    assert len(traversal._KEYS) <= traversal._KEYS.limit
