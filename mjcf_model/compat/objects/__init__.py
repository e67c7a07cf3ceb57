"""robosuite 1.5.2's object model (``models.objects``, ``models.base``) over immutable models.

Names, signatures, properties and output (``get_obj()``, ``asset``,
``get_xml()``: robosuite's attributes, in robosuite's order) are robosuite's, so
its code and pipeline (``ManipulationTask``, placement samplers, environments)
take these objects unchanged.

**State.** Each object holds one immutable ``<mujoco>`` node,
:attr:`~MujocoObject.mjcf`; each in-place ElementTree edit of robosuite
(prefixing, scaling, collision colours, materials) is a pure transform whose
result replaces it. robosuite's text habits (``"0.0 0.0 0.0"``, attribute
order, ``g<i>`` geom names, inline default classes) are reproduced exactly, and
attribute text read from files is kept as written.

**Memoisation.** Objects are made again at every reset, so what depends on the
input alone is remembered (:class:`~mjcf_model.caching.BoundedCache`):
file reads, XML object preparation, and prefix placement and recorded names per
*naming skeleton* (:mod:`~mjcf_model.compat.objects.naming`).

**Live ElementTree views.** ``get_obj()``, ``asset``, ``root``... are elements
of one view of the model (:class:`~serializers.etree_view.EtreeView`),
patched in place when the model changes: ``get_obj()`` is the same element on
every call, a later ``set_pos``/``set_scale`` shows in a task that appended it,
and an XML object's ``get_obj()`` is the element inside ``root``. Edits other
code makes to these elements stay in them but are not read back.

**isinstance.** A ``__class__`` property
(:class:`~mjcf_model.compat.objects.document.RobosuiteCompatible`) makes
instances pass ``isinstance`` against their robosuite twins
(``robosuite.models.objects.MujocoObject``...) without the library importing
robosuite, whenever robosuite is imported.

**Deliberate differences from robosuite.** Where robosuite crashes on valid
MJCF or builds a model MuJoCo rejects, this does the right thing:

* nested default classes are resolved (robosuite: ``KeyError``); ``childclass``
  is written inline (robosuite keeps and prefixes it; MuJoCo rejects that);
  the main default is dropped, as in robosuite;
* a geom without ``group`` is a collision geom (robosuite: ``TypeError``);
  ``MujocoXMLModel`` leaves unnamed geoms of groups 2 and up unnamed
  (robosuite: ``KeyError``);
* ``MujocoObject(scale=...)`` works (robosuite: ``TypeError``); numpy scalars
  work as attribute values and as a ``CompositeObject`` density, and whether
  a ``CompositeObject`` ``solimp`` is per geom depends on ``solimp`` alone
  (robosuite also consults ``obj_types``);
* references robosuite's attribute list misses (equality ``site1``/``site2``,
  ``refsite``, ``refname``) are prefixed, and a file asset without a name is
  named by its prefixed file stem (robosuite leaves dangling references);
* recorded ``sensors`` are all children of ``<sensor>`` (robosuite's tag list
  misses newer sensors);
* argument checks raise :class:`~mjcf_model.MjcfValueError` /
  :class:`~mjcf_model.MjcfLookupError` (``ValueError`` / ``KeyError``) saying
  what was expected, where robosuite asserts or fails later
  (``AttributeError``); ``correct_naming`` leaves ``None`` names alone
  (robosuite: ``TypeError``); scale factors must be finite and positive;
  ``MujocoXMLModel``'s ``contact_geom_rgba`` must be four numbers.

Side effects avoided: ``material="default"`` is MuJoCo's built-in flat texture
of the colour, not a PNG written to ``<tempdir>/robosuite_temp_tex/tex.png``
(shared by every object, so all showed the last colour);
``merge``/``merge_assets`` copy the other model's elements (robosuite shares
them); ``CompositeBodyObject`` leaves its children as they were (robosuite
strips, moves and renames their elements in place).

The composite recipes (``Bin``, ``Lid``, ``ConeObject``, ``HammerObject``...) keep
robosuite's quirks that show in the model or its properties: a
``PotWithHandlesObject``'s ``total_size`` is 3 x 3, a ``StandWithMount``'s hole
marker is named ``hole_vis_vis`` and its upright ``init_quat`` is an integer array,
a ``HammerObject`` without ``rng`` draws from a new unseeded generator and draws
again at each read of ``init_quat``. They differ where robosuite raises: a numpy
colour for a pot works (robosuite: ``ValueError``), and a bad hammer
``handle_shape`` or cone material raises :class:`~mjcf_model.MjcfValueError`
(robosuite asserts; the hammer raises after its draws, as robosuite's). A
``HookFrame`` tip builds no throw-away ``ConeObject``, and a
``RatchetingWrenchObject`` no unused grip material.

Further: ``BallObject`` and ``CapsuleObject`` take ``rng`` too (robosuite's
draw unseeded); white space text of the file is not kept (``get_xml()`` equals
robosuite's once white space is stripped); an element-level
``exclude_from_prefixing`` is consulted with names only;
``macros.USING_INSTANCE_RANDOMIZATION`` (off by default) is not consulted.

>>> can = CanObject("can")
>>> can.root_body, can.visual_geoms, can.important_sites
('can_main', ['can_g0_visual'], {'obj': 'can_default_site'})
>>> can.get_obj().get("name"), [child.tag for child in can.get_obj()]
('can_main', ['geom', 'geom', 'joint', 'site'])
"""

from __future__ import annotations

from mjcf_model.compat.objects.base import GEOM_GROUPS, GEOMTYPE2GROUP, MujocoModel, MujocoObject
from mjcf_model.compat.objects.composite import CompositeObject
from mjcf_model.compat.objects.composite_body import (
    CompositeBodyObject,
    HingedBoxObject,
    RatchetingWrenchObject,
)
from mjcf_model.compat.objects.containers import Bin, Lid, StandWithMount
from mjcf_model.compat.objects.generated import (
    BallObject,
    BoxObject,
    CapsuleObject,
    CylinderObject,
    MujocoGeneratedObject,
    PrimitiveObject,
)
from mjcf_model.compat.objects.pot import PotWithHandlesObject
from mjcf_model.compat.objects.shells import ConeObject, HollowCylinderObject
from mjcf_model.compat.objects.shipped import (
    BottleObject,
    BreadObject,
    BreadVisualObject,
    CanObject,
    CanVisualObject,
    CerealObject,
    CerealVisualObject,
    DoorObject,
    LemonObject,
    MilkObject,
    MilkVisualObject,
    PlateWithHoleObject,
    RoundNutObject,
    SquareNutObject,
)
from mjcf_model.compat.objects.tools import HammerObject, HookFrame
from mjcf_model.compat.objects.xml import MujocoXML, MujocoXMLModel, MujocoXMLObject

__all__ = [
    "GEOMTYPE2GROUP",
    "GEOM_GROUPS",
    "BallObject",
    "Bin",
    "BottleObject",
    "BoxObject",
    "BreadObject",
    "BreadVisualObject",
    "CanObject",
    "CanVisualObject",
    "CapsuleObject",
    "CerealObject",
    "CerealVisualObject",
    "CompositeBodyObject",
    "CompositeObject",
    "ConeObject",
    "CylinderObject",
    "DoorObject",
    "HammerObject",
    "HingedBoxObject",
    "HollowCylinderObject",
    "HookFrame",
    "LemonObject",
    "Lid",
    "MilkObject",
    "MilkVisualObject",
    "MujocoGeneratedObject",
    "MujocoModel",
    "MujocoObject",
    "MujocoXML",
    "MujocoXMLModel",
    "MujocoXMLObject",
    "PlateWithHoleObject",
    "PotWithHandlesObject",
    "PrimitiveObject",
    "RatchetingWrenchObject",
    "RoundNutObject",
    "SquareNutObject",
    "StandWithMount",
]
