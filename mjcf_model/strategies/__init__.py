"""Hypothesis strategies for MJCF nodes and whole models (``pip install mjcf-model[strategies]``).

Use them to property-test code that builds, edits or converts MJCF:

* :func:`models` draws complete models that MuJoCo compiles: a kinematic tree
  with free, ball, hinge and slide joints and a mocap body, geoms (inline meshes
  among them), sites, nested frames, a ``<replicate>``, cameras and lights that
  track bodies, nested default classes and ``childclass``, textures and
  materials, fixed and spatial tendons, actuators of every transmission (joint,
  jointinparent, tendon, site with or without refsite, body) some with
  activation, sensors, connect/weld/joint/tendon equalities, contact pairs and
  exclusions, a keyframe of the full state, and custom data, in degrees or
  radians, with lengths from millimetres to metres; every name is unique in
  its namespace and every reference resolves. Comments are sprinkled in.
* :func:`geoms`, :func:`joints`, :func:`sites`, :func:`bodies`, :func:`materials`
  draw single nodes that are valid where they stand.
* :func:`elements` draws any typed node class with arbitrary (well-formed, not
  necessarily meaningful) attribute values: for serializer round trips.

Example:
    >>> from hypothesis import given
    >>> from mjcf_model import dumps, loads
    >>> @given(models())
    ... def test_round_trip(model):
    ...     assert loads(dumps(model)) == model
    >>> test_round_trip()

"""

from mjcf_model.strategies.drawn_elements import (
    element_values,
    elements,
    geoms,
    joints,
    materials,
    sites,
)
from mjcf_model.strategies.drawn_models import bodies, models
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
