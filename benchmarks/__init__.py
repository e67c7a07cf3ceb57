"""Benchmarks: mjcf-model beside the tools people would otherwise use, as ratios.

Run ``python -m benchmarks`` (``--tiny`` for a quick check); see :mod:`benchmarks.__main__`.
Each case runs every contender on the same inputs in one process, several times,
and reports the median and the ratio to mjcf-model. Nothing here is a test: CI
only runs the runner once on tiny inputs to keep it working.
"""
