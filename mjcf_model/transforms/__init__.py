"""Pure transforms: functions named for their result that return changed copies.

:mod:`~mjcf_model.transforms.naming` renames and prefixes,
:mod:`~mjcf_model.transforms.scaling` scales, and :mod:`~mjcf_model.transforms.composition`
attaches models to each other.
The input never changes; unchanged subtrees are shared.
"""
