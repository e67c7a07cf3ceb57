"""The ``<compiler>`` settings a model is read under, and how attaching treats each.

>>> from mjcf_model import loads
>>> compiler_settings(loads('<mujoco><compiler angle="radian"/></mujoco>'))["angle"]
'radian'
"""

from __future__ import annotations

from collections.abc import Mapping

from mjcf_model.errors import MjcfValueError
from mjcf_model.nodes.base import attribute_items
from mjcf_model.nodes.root import Mujoco
from mjcf_model.values import format_value

__all__ = [
    "CONVERTED_SETTINGS",
    "INERTIA_SETTINGS",
    "MODEL_WIDE_SETTINGS",
    "NUMERIC_SETTINGS",
    "PATH_SETTINGS",
    "Settings",
    "compiler_settings",
]

#: Setting name to its text, for one model.
Settings = dict[str, str]

#: The settings :func:`~mjcf_model.transforms.composition.conventions.in_conventions`
#: keeps per child (see its module's table), each with MuJoCo's value where no
#: ``<compiler>`` writes it.
CONVERTED_SETTINGS: Mapping[str, str] = {
    "alignfree": "false",
    "angle": "degree",
    "autolimits": "true",
    "balanceinertia": "false",
    "boundinertia": "0",
    "boundmass": "0",
    "eulerseq": "xyz",
    "fitaabb": "false",
    "inertiafromgeom": "auto",
    "inertiagrouprange": "0 5",
    "settotalmass": "-1",
}
#: Settings that name folders and files: left to the code that relocates file paths.
PATH_SETTINGS = frozenset({"assetdir", "meshdir", "strippath", "texturedir"})
#: Settings (and ``<compiler>`` child elements) that hold for a whole model: the parent's stay.
MODEL_WIDE_SETTINGS = frozenset(
    [
        "conflict",
        "coordinate",
        "discardvisual",
        "fusestatic",
        "lengthrange",
        "passthrough",
        "savecanonical",
        "savecompiled",
        "saveinertial",
        "usethread",
    ]
)
#: The settings that change the mass and inertia MuJoCo gives a body.
INERTIA_SETTINGS = (
    "balanceinertia",
    "boundinertia",
    "boundmass",
    "inertiafromgeom",
    "inertiagrouprange",
    "settotalmass",
)
NUMERIC_SETTINGS = frozenset({"boundinertia", "boundmass", "inertiagrouprange", "settotalmass"})


def compiler_settings(model: Mujoco) -> Settings:
    """The compiler settings MuJoCo reads for ``model``: its sections merged, later ones winning.

    Settings of :data:`CONVERTED_SETTINGS` no section writes have MuJoCo's default.

    Raises:
        MjcfValueError: ``eulerseq`` is not 3 characters long (MuJoCo rejects it).

    Examples:
        >>> from mjcf_model import loads
        >>> m = loads('<mujoco><compiler angle="radian"/><compiler angle="degree"/></mujoco>')
        >>> compiler_settings(m)["angle"], compiler_settings(m)["eulerseq"]
        ('degree', 'xyz')

    """
    settings = dict(CONVERTED_SETTINGS)
    for section in model.elements:
        if section.tag == "compiler":
            settings.update((k, format_value(v)) for k, v in attribute_items(section))
    if len(settings["eulerseq"]) != 3:
        raise MjcfValueError(
            f"<compiler eulerseq={settings['eulerseq']!r}>: MuJoCo reads a sequence of exactly "
            "3 axes, such as 'xyz' (intrinsic) or 'XYZ' (extrinsic)"
        )
    return settings
