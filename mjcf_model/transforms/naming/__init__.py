"""Names: which a model declares, and renaming or prefixing them with every reference.

>>> from mjcf_model import Body, Geom
>>> prefixed(Body(name="arm", children=[Geom(name="g")]), "r_").children[0].name
'r_g'
"""

from mjcf_model.transforms.naming.renaming import (
    declared_names,
    prefix_map,
    prefixed,
    prefixed_declared,
    renamed,
)

__all__ = ["declared_names", "prefix_map", "prefixed", "prefixed_declared", "renamed"]
