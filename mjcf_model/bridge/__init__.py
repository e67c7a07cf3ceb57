"""The MuJoCo bridge: the layer that hands models to MuJoCo and reads compiled models.

:mod:`~mjcf_model.bridge.compiling` compiles a model in memory (``compiled``),
:mod:`~mjcf_model.bridge.compile_errors` follows MuJoCo's complaint back to the
user's file, line and element, :mod:`~mjcf_model.bridge.patching` applies
physical edits to a compiled model (``patched``),
:mod:`~mjcf_model.bridge.batching` stacks the fields variants change, one row per world
(``batched``), and :mod:`~mjcf_model.bridge.compare` compares compiled models field by
field.
Everything below this layer works without MuJoCo.
"""
