"""Composing models: attaching one model to another as MuJoCo compiles both.

:func:`attach` merges a child model into a parent at a body, frame or site,
each keeping its meaning under its own ``<compiler>``;
:func:`inlined_attachments` expands MuJoCo's own ``<attach>`` elements.
"""

from mjcf_model.transforms.composition.attaching import attach, attach_all
from mjcf_model.transforms.composition.inlining import inlined_attachments

__all__ = ["attach", "attach_all", "inlined_attachments"]
