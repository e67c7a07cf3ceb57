"""The root ``<mujoco>`` element and ``<include>``.

>>> from mjcf_model.nodes.body import Worldbody
>>> Mujoco(model="m", children=[Worldbody()]).worldbody
Worldbody()
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import ClassVar

import attrs

from mjcf_model.nodes.actuator import Actuator
from mjcf_model.nodes.asset import Asset
from mjcf_model.nodes.base import TypedElement
from mjcf_model.nodes.body import Worldbody
from mjcf_model.nodes.compiler import Compiler, Option, Size, Statistic
from mjcf_model.nodes.contact import Contact
from mjcf_model.nodes.custom import Custom
from mjcf_model.nodes.declaring import node
from mjcf_model.nodes.default import Default
from mjcf_model.nodes.deformable import Deformable
from mjcf_model.nodes.equality import Equality
from mjcf_model.nodes.fields import text
from mjcf_model.nodes.keyframe import Keyframe
from mjcf_model.nodes.plugin import Extension
from mjcf_model.nodes.sensor import Sensor
from mjcf_model.nodes.tendon import Tendon
from mjcf_model.nodes.visual import Visual


def to_base_dir(value: str | os.PathLike[str] | None) -> Path | None:
    """An absolute folder path, or ``None``.

    Examples:
        >>> to_base_dir("/robots/panda")
        PosixPath('/robots/panda')

    """
    return None if value is None else Path(os.path.abspath(value))


__all__ = ["Include", "Mujoco"]


@node
class Include(TypedElement):
    """Includes another MJCF file's elements here."""

    schema_keys: ClassVar[tuple[str, ...]] = ("include",)
    #: File name, relative to the model (or asset) directory.
    file: str | None = text()


@node
class Mujoco(TypedElement):
    """The root of an MJCF model."""

    schema_keys: ClassVar[tuple[str, ...]] = ("mujoco",)
    #: Name of the model asset.
    model: str | None = text()
    #: The folder the model's relative file paths (meshes, textures, includes, ...)
    #: resolve from: the loaded file's folder, or ``None`` for a model built in code,
    #: whose paths resolve from wherever it is compiled or written. Where a model's
    #: files are is not part of its value (``==`` and ``hash`` ignore it); the dict
    #: form keeps it, so a model read back from its dict still finds its files.
    base_dir: Path | None = attrs.field(default=None, eq=False, repr=False, converter=to_base_dir)

    @property
    def compiler(self) -> Compiler | None:
        """The first ``<compiler>`` section, or ``None``."""
        return self._first(Compiler)

    @property
    def option(self) -> Option | None:
        """The first ``<option>`` section, or ``None``."""
        return self._first(Option)

    @property
    def size(self) -> Size | None:
        """The first ``<size>`` section, or ``None``."""
        return self._first(Size)

    @property
    def statistic(self) -> Statistic | None:
        """The first ``<statistic>`` section, or ``None``."""
        return self._first(Statistic)

    @property
    def visual(self) -> Visual | None:
        """The first ``<visual>`` section, or ``None``."""
        return self._first(Visual)

    @property
    def default(self) -> Default | None:
        """The first ``<default>`` section, or ``None``."""
        return self._first(Default)

    @property
    def asset(self) -> Asset | None:
        """The first ``<asset>`` section, or ``None``."""
        return self._first(Asset)

    @property
    def worldbody(self) -> Worldbody | None:
        """The first ``<worldbody>`` section, or ``None``."""
        return self._first(Worldbody)

    @property
    def deformable(self) -> Deformable | None:
        """The first ``<deformable>`` section, or ``None``."""
        return self._first(Deformable)

    @property
    def contact(self) -> Contact | None:
        """The first ``<contact>`` section, or ``None``."""
        return self._first(Contact)

    @property
    def equality(self) -> Equality | None:
        """The first ``<equality>`` section, or ``None``."""
        return self._first(Equality)

    @property
    def tendon(self) -> Tendon | None:
        """The first ``<tendon>`` section, or ``None``."""
        return self._first(Tendon)

    @property
    def actuator(self) -> Actuator | None:
        """The first ``<actuator>`` section, or ``None``."""
        return self._first(Actuator)

    @property
    def sensor(self) -> Sensor | None:
        """The first ``<sensor>`` section, or ``None``."""
        return self._first(Sensor)

    @property
    def keyframe(self) -> Keyframe | None:
        """The first ``<keyframe>`` section, or ``None``."""
        return self._first(Keyframe)

    @property
    def custom(self) -> Custom | None:
        """The first ``<custom>`` section, or ``None``."""
        return self._first(Custom)

    @property
    def extension(self) -> Extension | None:
        """The first ``<extension>`` section, or ``None``."""
        return self._first(Extension)
