"""Where a model's files are, and the one PNG writer.

:mod:`~mjcf_model.files.provenance` resolves asset, include and sub-model
paths as MuJoCo does; :mod:`~mjcf_model.files.png` writes pictures and flat
textures as PNG files.
"""
