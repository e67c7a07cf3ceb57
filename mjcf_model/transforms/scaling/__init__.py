"""Scaling a model: every length multiplied, angles and unitless values untouched.

:mod:`~mjcf_model.transforms.scaling.transform` is the transform;
:mod:`~mjcf_model.transforms.scaling.rules` holds the rule of every schema key,
built from the pieces in :mod:`~mjcf_model.transforms.scaling.pieces`, which
read :mod:`~mjcf_model.transforms.scaling.context`.

>>> from mjcf_model import Geom
>>> scaled(Geom(type="sphere", size=[0.1]), 2).size
(0.2,)
"""

from mjcf_model.transforms.scaling.transform import MassPolicy, scaled

__all__ = ["MassPolicy", "scaled"]
