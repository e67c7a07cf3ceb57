"""Hypothesis strategies for MJCF nodes and whole models (``pip install mjcf-model[strategies]``).

Use them to property-test code that builds, edits or converts MJCF:

* :func:`models` draws complete models that MuJoCo compiles: a kinematic tree
  with joints, geoms, sites, cameras and lights, frames, default classes,
  textures and materials, actuators, sensors, tendons, equality constraints,
  contact pairs and exclusions, a keyframe and custom data; every name is
  unique in its namespace and every reference resolves. Comments are sprinkled in.
* :func:`geoms`, :func:`joints`, :func:`sites`, :func:`bodies`, :func:`materials`
  draw single nodes that are valid where they stand.
* :func:`elements` draws any typed node class with arbitrary (well-formed, not
  necessarily meaningful) attribute values: for serializer round trips.

Example:
    >>> from hypothesis import given
    >>> from serializers import dumps, loads
    >>> @given(models())
    ... def test_round_trip(model):
    ...     assert loads(dumps(model)) == model
    >>> test_round_trip()

"""

from mjcf_model.strategies.elements import element_values, elements, geoms, joints, materials, sites
from mjcf_model.strategies.models import bodies, models
from mjcf_model.strategies.primitives import comments, names

__all__ = [
    "bodies",
    "comments",
    "element_values",
    "elements",
    "geoms",
    "joints",
    "materials",
    "models",
    "names",
    "sites",
]
