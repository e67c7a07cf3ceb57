"""The round-trip check behind ``mjcf-model check``: load, write, compile both, compare.

>>> import pathlib, tempfile
>>> path = pathlib.Path(tempfile.mkdtemp()) / "m.xml"
>>> _ = path.write_text("<mujoco><worldbody><geom size='0.1'/></worldbody></mujoco>")
>>> result = check_file(path)
>>> result.status, result.differences
('identical', ())
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any, Literal

import attrs

from mjcf_model.errors import MjcfError
from mjcf_model.files.compiling import compiled
from mjcf_model.tools.compare import model_differences, path_fields

__all__ = ["CheckResult", "check_file", "written_differences"]

#: ``identical``: both compile to the same model; ``different``: they compile to
#: different models; ``not-compiled``: MuJoCo rejects the original itself;
#: ``error``: mjcf-model could not read or write it, or the round trip does not compile.
Status = Literal["identical", "different", "not-compiled", "error"]


@attrs.frozen(kw_only=True)
class CheckResult:
    """The outcome of checking one file."""

    #: The file checked.
    path: str
    #: What happened.
    status: Status
    #: The ``MjModel`` fields that differ (for ``different``).
    differences: tuple[str, ...] = ()
    #: The error message (for ``error`` and ``not-compiled``).
    message: str = ""

    @property
    def ok(self) -> bool:
        """Whether the round trip compiled to the identical model."""
        return self.status == "identical"


def check_file(path: str | os.PathLike[str], *, inline_includes: bool = False) -> CheckResult:
    """Round-trip one MJCF file and compare the compiled models.

    Loads the file, writes it back to text, compiles the original and, in
    memory (:func:`mjcf_model.compiled`), the written text read as if it stood
    in the original's folder, and compares every field of the two ``MjModel``
    objects but the recorded file paths (:func:`mjcf_model.tools.compare.path_fields`).

    Example:
        >>> check_file("/no/such/file.xml").status
        'error'

    """
    import mujoco

    from serializers import dumps, load

    name = str(path)
    if not Path(path).is_file():
        return CheckResult(path=name, status="error", message="no such file")
    try:
        original = mujoco.MjModel.from_xml_path(name)
    except ValueError as error:
        return CheckResult(path=name, status="not-compiled", message=str(error).strip())
    try:
        written = dumps(load(path, inline_includes=inline_includes))
        differences = written_differences(original, written, name)
    except MjcfError as error:
        return CheckResult(path=name, status="error", message=str(error))
    status: Status = "different" if differences else "identical"
    return CheckResult(path=name, status=status, differences=differences)


def written_differences(original: Any, written: str, path: str) -> tuple[str, ...]:
    """The ``MjModel`` fields in which ``written`` compiles differently from ``original``.

    ``written`` is read as if it were the file ``path`` (its relative files resolve
    from there) and compiled in memory; recorded file paths are not compared.

    Raises:
        MjcfError: ``written`` cannot be read, or does not compile (the message says so).

    Example:
        >>> import mujoco
        >>> original = mujoco.MjModel.from_xml_string("<mujoco><worldbody/></mujoco>")
        >>> written_differences(original, "<mujoco/>", "m.xml")
        ()

    """
    from serializers import loads

    reread = loads(written, base_dir=Path(path).parent, filename=path)
    try:
        again = compiled(reread)
    except MjcfError as error:
        raise type(error)(f"the written model does not compile: {error.detail}") from error
    return tuple(model_differences(original, again, ignore=path_fields()))
