"""Tools over whole models: comparing compiled models, the round-trip check, the command line."""
