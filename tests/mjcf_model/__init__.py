# Run pytest from the repository root: from inside tests/ this folder would be imported as
# the package it tests.
if __name__ != "tests.mjcf_model":
    raise ImportError("tests/mjcf_model is not the package: run pytest from the repository root")
