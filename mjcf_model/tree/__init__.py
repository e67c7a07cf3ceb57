"""The tree toolkit: walking and rebuilding node trees, looking things up, default classes.

:mod:`~mjcf_model.tree.traversal` walks a tree and rebuilds only the changed
paths; :mod:`~mjcf_model.tree.queries` finds elements; :mod:`~mjcf_model.tree.defaults`
says which default class an element takes its unwritten values from.
"""
