"""Where a model's files are, and compiling a model with them in memory.

:mod:`~mjcf_model.files.provenance` resolves asset, include and sub-model
paths as MuJoCo does; :mod:`~mjcf_model.files.compiling` compiles a model
through MuJoCo's asset dictionary and gathers the files it uses.
"""
