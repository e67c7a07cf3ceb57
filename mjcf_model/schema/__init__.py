"""The MJCF schema as data: every element and attribute, and the keyword sets.

:mod:`~mjcf_model.schema.namespaces` is the one table saying which names each
element declares and which namespace each reference points to; prefixing,
reference checks and the strategies all read it.
"""
