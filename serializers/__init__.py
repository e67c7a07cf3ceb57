"""Lossless MJCF serializers: text, files, ElementTree and dicts.

``load``/``loads``/``dump``/``dumps`` work like :mod:`json`; ``to_etree`` and
``from_etree`` convert to and from :mod:`xml.etree.ElementTree`; ``to_dict`` and
``from_dict`` give JSON-safe dicts through one cattrs converter.

>>> model = loads('<mujoco><worldbody><body name="b"/></worldbody></mujoco>')
>>> loads(dumps(model)) == model
True
"""

from mjcf_model.serializers.collector import collector_paused
from mjcf_model.serializers.dicts import from_dict, make_converter, to_dict
from mjcf_model.serializers.dumping import dump, dumps
from mjcf_model.serializers.etree import from_etree, to_etree
from mjcf_model.serializers.exporting import export
from mjcf_model.serializers.loading import load, loads

__all__ = [
    "collector_paused",
    "dump",
    "dumps",
    "export",
    "from_dict",
    "from_etree",
    "load",
    "loads",
    "make_converter",
    "to_dict",
    "to_etree",
]
