# Run pytest from the repository root: from inside tests/ this folder would be imported as
# the package it tests.
if __name__ != "tests.serializers":
    raise ImportError("tests/serializers is not the package: run pytest from the repository root")
