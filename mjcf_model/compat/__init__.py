"""robosuite-compatible layer: ``mjcf_utils`` functions and the ``MujocoObject`` family.

Code written against robosuite 1.5.2's ``robosuite.utils.mjcf_utils`` and
``robosuite.models.objects`` runs unchanged against :mod:`mjcf_model.compat.mjcf_utils`
and :mod:`mjcf_model.compat.objects`. The state underneath is the immutable model;
every behaviour is a call into the pure transforms of :mod:`mjcf_model`, and
ElementTree appears only at the boundary, as robosuite's own code expects.

The robosuite conventions that are not robosuite's own API are here too, not in
:mod:`mjcf_model`: its materials on nodes (:func:`with_material`,
:func:`recolored_collision_geoms`, with robosuite's :class:`CustomMaterial`), its geom
categories (:func:`categorized`) and its constructors as typed nodes (``new_body``...).
"""

from mjcf_model.compat import materials, typed_builders
from mjcf_model.compat.materials import *
from mjcf_model.compat.mjcf_utils.queries import Categories, categorized
from mjcf_model.compat.typed_builders import *

__all__ = ["Categories", "categorized", *materials.__all__, *typed_builders.__all__]
