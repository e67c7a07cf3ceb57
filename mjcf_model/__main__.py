"""``python -m mjcf_model``: the same as the ``mjcf-model`` command."""

import sys

from mjcf_model.tools.cli import main

sys.exit(main())
