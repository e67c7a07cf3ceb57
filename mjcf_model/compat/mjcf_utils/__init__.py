"""robosuite 1.5.2's ``robosuite.utils.mjcf_utils``, over the immutable model.

Every public name of robosuite's module is here with the same signature and the
same observable behaviour (return values, in-place edits of the live ElementTree
elements, number text), so robosuite code runs after replacing the import::

    from mjcf_model.compat import mjcf_utils  # instead of robosuite.utils.mjcf_utils

Each tree function converts the element to generic nodes, calls a pure function
on them, and writes the result back onto the same elements (never replacing one).

Where it differs from robosuite on purpose is listed in the guide's robosuite page.

>>> import xml.etree.ElementTree as ET
>>> obj = ET.fromstring('<body name="can"><geom name="g" mesh="can_mesh"/></body>')
>>> add_prefix(obj, "can_")
>>> ET.tostring(obj, encoding="unicode")
'<body name="can_can"><geom name="can_g" mesh="can_mesh" /></body>'
"""

from __future__ import annotations

from mjcf_model.compat.mjcf_utils import (
    builders,
    constants,
    materials,
    naming,
    queries,
    scaling,
    text,
)
from mjcf_model.compat.mjcf_utils.builders import *
from mjcf_model.compat.mjcf_utils.constants import *
from mjcf_model.compat.mjcf_utils.materials import *
from mjcf_model.compat.mjcf_utils.naming import *
from mjcf_model.compat.mjcf_utils.queries import *
from mjcf_model.compat.mjcf_utils.queries import _element_filter as _element_filter
from mjcf_model.compat.mjcf_utils.scaling import *
from mjcf_model.compat.mjcf_utils.text import *

# Each module lists its share of robosuite's public names; ``_element_filter`` is
# importable by name, as in robosuite, but private: not in ``__all__``.
__all__ = (
    builders.__all__
    + constants.__all__
    + materials.__all__
    + naming.__all__
    + queries.__all__
    + scaling.__all__
    + text.__all__
)
