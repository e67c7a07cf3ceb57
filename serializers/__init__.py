"""Lossless MJCF serializers: text, files, ElementTree and dicts.

``load``/``loads``/``dump``/``dumps`` work like :mod:`json`; ``to_etree`` and
``from_etree`` convert to and from :mod:`xml.etree.ElementTree`; ``to_dict`` and
``from_dict`` give JSON-safe dicts through one cattrs converter.

>>> model = loads('<mujoco><worldbody><body name="b"/></worldbody></mujoco>')
>>> loads(dumps(model)) == model
True
"""

from serializers.dicts import from_dict, to_dict
from serializers.etree_reading import from_etree
from serializers.exporting import export
from serializers.reader import load, loads
from serializers.writer import dump, dumps, to_etree

__all__ = [
    "dump",
    "dumps",
    "export",
    "from_dict",
    "from_etree",
    "load",
    "loads",
    "to_dict",
    "to_etree",
]
