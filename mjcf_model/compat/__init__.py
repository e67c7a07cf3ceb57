"""robosuite-compatible layer: ``mjcf_utils`` functions and the ``MujocoObject`` family.

Code written against robosuite 1.5.2's ``robosuite.utils.mjcf_utils`` and
``robosuite.models.objects`` runs unchanged against :mod:`mjcf_model.compat.mjcf_utils`
and :mod:`mjcf_model.compat.objects`. The state underneath is the immutable model;
every behaviour is a call into the pure transforms of :mod:`mjcf_model`, and
ElementTree appears only at the boundary, as robosuite's own code expects.
"""
