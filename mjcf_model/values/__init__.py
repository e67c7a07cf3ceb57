"""Attribute values: the one place where MJCF text becomes Python values and back.

Node fields hold ``str``, ``int``, ``float``, ``bool`` or tuples of numbers. The
converters below are the attrs converters of those fields: they accept MJCF
text (as the reader hands it over), Python numbers, any sequence and numpy
arrays, and raise :class:`~mjcf_model.errors.MjcfValueError` on a wrong count
or a non-number. :func:`format_value` is their inverse and the only place that
formats numbers: floats are written with the shortest text that reads back to
the same double, so MuJoCo compiles the written model bit for bit the same.

>>> to_vec3("0 0.1 2")
(0.0, 0.1, 2.0)
>>> format_value((0.0, 0.1, 2.0))
'0 0.1 2'
>>> format_value(True)
'true'
"""

from mjcf_model.values.kinds import (
    Floats,
    Ints,
    Unparsed,
    Value,
    check_name,
    check_text,
    float_key,
)
from mjcf_model.values.reading import (
    OneOf,
    float_from_text,
    floats_from_text,
    numbers_of,
    one_of,
    text_reader,
    to_bool,
    to_float,
    to_floats,
    to_int,
    to_ints,
    to_str,
    to_vec1to2,
    to_vec1to3,
    to_vec1to5,
    to_vec2,
    to_vec3,
    to_vec4,
    to_vec6,
)
from mjcf_model.values.writing import (
    format_float,
    format_value,
    plain_value,
)

__all__ = [
    "Floats",
    "Ints",
    "OneOf",
    "Unparsed",
    "Value",
    "check_name",
    "check_text",
    "float_from_text",
    "float_key",
    "floats_from_text",
    "format_float",
    "format_value",
    "numbers_of",
    "one_of",
    "plain_value",
    "text_reader",
    "to_bool",
    "to_float",
    "to_floats",
    "to_int",
    "to_ints",
    "to_str",
    "to_vec1to2",
    "to_vec1to3",
    "to_vec1to5",
    "to_vec2",
    "to_vec3",
    "to_vec4",
    "to_vec6",
]
