"""robosuite's object model (``models.objects``, ``models.base``) over immutable models.

The classes keep robosuite 1.5.2's names, signatures, properties and output
(``get_obj()``, ``asset`` and ``get_xml()`` are, attribute for attribute and in
the same order, what robosuite builds), so code written for robosuite runs
unchanged; robosuite's own pipeline (``ManipulationTask``, placement samplers,
environments) accepts them.

**State.** Each object holds one immutable model, :attr:`~MujocoObject.mjcf`:
a ``<mujoco>`` node (for a generated object, ``<mujoco><asset/><worldbody>``
around its body). Every step robosuite performs by editing ElementTree in place
is a pure transform here, whose result replaces the model: prefixing
(:func:`~mjcf_model.prefixed`, with robosuite's "skip what already starts
with the prefix" as its ``exclude``), scaling and collision colours (the pure
functions behind the compatible ``mjcf_utils``'s ``scale_mjcf_model`` and
``recolor_collision_geoms``, which robosuite's classes call), materials
(:class:`~mjcf_model.CustomMaterial`), categories
(:func:`~mjcf_model.categorized`). robosuite's habits (number text such as
``"0.0 0.0 0.0"``, attribute order, visual twins of collision geoms, unnamed
geoms numbered ``g<i>``, default classes written inline) are small functions
on nodes in :mod:`~mjcf_model.compat.objects.habits` and
:mod:`~mjcf_model.compat.objects.reading`, built on the compatible
``mjcf_utils`` (``mjcf_model.compat.mjcf_utils``) wherever robosuite's objects
call it. Attribute text is kept exactly (nodes are generic elements), because
robosuite passes it on unchanged.

**Made again and again.** Environments make the same objects at every reset,
and nodes never change, so what an object computes from its input alone is
remembered (:mod:`~mjcf_model.compat.objects.memo`): a file is read once per
modification, an XML object's geom split once per file and choice of joints,
and where the name prefix goes and which names robosuite records once per
*naming skeleton* (:mod:`~mjcf_model.compat.objects.naming`), which objects of
one kind share whatever their sizes; each new object then only writes its
prefix.

**What** ``get_obj()``, ``asset``, ``root``... **return.** Live ElementTree
elements of one view of the model, built when first read and then patched in
place whenever the model changes (:class:`~mjcf_model.compat.objects.etree_view.EtreeView`):
``get_obj()`` is the same element on every call, ``set_pos`` or
``set_scale`` after ``task.worldbody.append(obj.get_obj())`` shows in the
task, and ``get_obj()`` of an XML object is the very element inside ``root``,
all as in robosuite, where the object is its ElementTree. Edits other code
makes to those elements (robosuite's environments set ``pos``/``quat`` on
them) stay in the elements but are not read back: the model is the truth.

**robosuite's** ``isinstance`` **checks.** Instances answer
``isinstance(obj, robosuite.models.objects.MujocoObject)`` (and every
robosuite twin of their class) through a ``__class__`` property: see
:mod:`~mjcf_model.compat.objects.class_face`. robosuite is never imported by the
library and may be imported before or after objects are made.

**Where this differs from robosuite on purpose.** Where robosuite crashes on
valid MJCF or builds a model MuJoCo rejects, this does the right thing:

* nested default classes are resolved (robosuite: ``KeyError``), and
  ``childclass`` is written inline (robosuite keeps it, prefixes it, and MuJoCo
  rejects the model); the main default is dropped, as robosuite drops it;
* a geom without ``group`` is a collision geom (robosuite: ``TypeError``), and
  ``MujocoXMLModel`` leaves unnamed geoms of groups 2 and up unnamed
  (robosuite: ``KeyError``);
* ``MujocoObject(scale=...)`` works (robosuite: ``TypeError``); numpy scalars
  work as attribute values and as a ``CompositeObject`` density;
* references robosuite's attribute list misses (equality ``site1``/``site2``,
  ``refsite``, ``refname``) are prefixed with their targets, and a file asset
  without a name gets its prefixed stem as name (robosuite leaves dangling
  references);
* argument checks raise :class:`~mjcf_model.MjcfValueError` /
  :class:`~mjcf_model.MjcfLookupError` (``ValueError`` / ``KeyError``) with
  what was expected, where robosuite uses ``assert`` or fails later with
  ``AttributeError``; ``correct_naming`` leaves ``None`` names alone (robosuite:
  ``TypeError``); scale factors must be positive.

And where robosuite has a side effect this library avoids: the
``material="default"`` texture is MuJoCo's built-in flat texture of the
colour, not a PNG written to ``<tempdir>/robosuite_temp_tex/tex.png`` (one
file shared by every object, so all showed the last colour). Further:
``merge``/``merge_assets`` copy the other model's elements (robosuite shares
the element objects), and ``CompositeBodyObject`` leaves its children as they
were (robosuite strips, moves and renames their elements in place); white
space text of the file is not kept (``get_xml()`` equals robosuite's once
white space is stripped); an element-level
``exclude_from_prefixing`` is consulted with names only; robosuite's
``macros.USING_INSTANCE_RANDOMIZATION`` (off by default) is not consulted.

>>> can = CanObject("can")
>>> can.root_body, can.visual_geoms, can.important_sites
('can_main', ['can_g0_visual'], {'obj': 'can_default_site'})
>>> can.get_obj().get("name"), [child.tag for child in can.get_obj()]
('can_main', ['geom', 'geom', 'joint', 'site'])
"""

from __future__ import annotations

from mjcf_model.compat.objects.base import (
    GEOM_GROUPS,
    GEOMTYPE2GROUP,
    MujocoModel,
    MujocoObject,
)
from mjcf_model.compat.objects.composite import CompositeObject
from mjcf_model.compat.objects.composite_body import CompositeBodyObject, HingedBoxObject
from mjcf_model.compat.objects.generated import MujocoGeneratedObject, PrimitiveObject
from mjcf_model.compat.objects.primitives import (
    BallObject,
    BoxObject,
    CapsuleObject,
    CylinderObject,
)
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
from mjcf_model.compat.objects.xml import MujocoXML, MujocoXMLObject
from mjcf_model.compat.objects.xml_model import MujocoXMLModel

__all__ = [
    "GEOMTYPE2GROUP",
    "GEOM_GROUPS",
    "BallObject",
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
    "CylinderObject",
    "DoorObject",
    "HingedBoxObject",
    "LemonObject",
    "MilkObject",
    "MilkVisualObject",
    "MujocoGeneratedObject",
    "MujocoModel",
    "MujocoObject",
    "MujocoXML",
    "MujocoXMLModel",
    "MujocoXMLObject",
    "PlateWithHoleObject",
    "PrimitiveObject",
    "RoundNutObject",
    "SquareNutObject",
]
