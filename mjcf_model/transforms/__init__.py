"""Pure transforms: functions named for their result that return changed copies.

:mod:`~mjcf_model.transforms.naming` renames and prefixes,
:mod:`~mjcf_model.transforms.scaling` scales, :mod:`~mjcf_model.transforms.composition`
attaches models to each other, :mod:`~mjcf_model.transforms.recolouring` recolours collision geoms.
The input never changes; unchanged subtrees are shared.
"""
