"""robosuite 1.5.2's object model (``models.objects``, ``models.base``) over immutable models.

Names, signatures, properties and output (``get_obj()``, ``asset``, ``get_xml()``:
robosuite's attributes, in robosuite's order) are robosuite's, so its code and pipeline
(``ManipulationTask``, placement samplers, environments) take these objects unchanged.

Each object holds one immutable ``<mujoco>`` node, :attr:`~MujocoObject.mjcf`: each
in-place edit robosuite makes (prefixing, scaling, colours, materials) is a pure transform
whose result replaces it, and ``get_obj()``, ``asset``, ``root``... are elements of one
live ElementTree view of it, patched in place, so a later ``set_pos`` shows in a task that
appended the object (:mod:`~mjcf_model.compat.objects.document`, which also makes
instances pass ``isinstance`` against robosuite's classes). robosuite's text habits
(``"0.0 0.0 0.0"``, attribute order, ``g<i>`` geom names, inline default classes) are
reproduced exactly. Objects are made again at every reset, so what depends on the input
alone is remembered in bounded caches: file reads, prepared XML objects, and names per
naming skeleton (:mod:`~mjcf_model.compat.objects.naming`). Where this differs from
robosuite on purpose is listed in the guide's robosuite page.

>>> can = CanObject("can")
>>> can.root_body, can.visual_geoms, can.important_sites
('can_main', ['can_g0_visual'], {'obj': 'can_default_site'})
>>> can.get_obj().get("name"), [child.tag for child in can.get_obj()]
('can_main', ['geom', 'geom', 'joint', 'site'])
"""

from __future__ import annotations

from mjcf_model.compat.objects import (
    base,
    composite,
    composite_body,
    containers,
    generated,
    pot,
    shells,
    shipped,
    tools,
    xml,
)
from mjcf_model.compat.objects.base import *
from mjcf_model.compat.objects.composite import *
from mjcf_model.compat.objects.composite_body import *
from mjcf_model.compat.objects.containers import *
from mjcf_model.compat.objects.generated import *
from mjcf_model.compat.objects.pot import *
from mjcf_model.compat.objects.shells import *
from mjcf_model.compat.objects.shipped import *
from mjcf_model.compat.objects.tools import *
from mjcf_model.compat.objects.xml import *

# Each module lists the robosuite classes (and constants) it defines.
__all__ = (
    base.__all__
    + composite.__all__
    + composite_body.__all__
    + containers.__all__
    + generated.__all__
    + pot.__all__
    + shells.__all__
    + shipped.__all__
    + tools.__all__
    + xml.__all__
)
