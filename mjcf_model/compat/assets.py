"""Where robosuite's asset files are (textures, meshes, object files), found without importing it.

>>> assets_root().endswith("models/assets")
True
"""

from __future__ import annotations

import importlib.util
import os

from mjcf_model.errors import MjcfLookupError

__all__ = ["assets_root"]


def assets_root(missing: str | None = None) -> str:
    """The ``models/assets`` directory of robosuite, found without importing it.

    Raises ``MjcfLookupError`` (with message ``missing``, if given) when robosuite is absent.
    """
    spec = importlib.util.find_spec("robosuite")
    if spec is None or not spec.submodule_search_locations:
        raise MjcfLookupError(
            missing
            or "robosuite's asset files (named textures, relative asset paths) are needed, "
            "but robosuite is not installed; install robosuite or give an absolute path"
        )
    return os.path.join(next(iter(spec.submodule_search_locations)), "models", "assets")
