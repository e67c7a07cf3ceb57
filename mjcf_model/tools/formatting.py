"""The canonical form of an MJCF file, and the proof that it compiles to the same model.

:func:`format_text` rewrites MJCF text in the form the writer produces for a model
built in code (``dumps(model, canonical=True)``: two-space indentation, one element
a line, numbers in their shortest form, comments kept). A rewrite is only offered
with a proof that nothing changed:

* ``"compiled"``: MuJoCo compiles the original and the rewrite to the identical
  model (every ``MjModel`` field but the recorded file paths);
* ``"elements"``: MuJoCo rejects the original itself (a fragment for ``<include>``,
  a model whose meshes are elsewhere), so the rewrite is read back and compared
  element by element (:func:`mjcf_model.tools.diff.changes_between`) instead.

When the proof fails, :attr:`Formatted.differences` says what would change and
the rewrite must not be written.

>>> result = format_text("<mujoco><worldbody><geom size='0.10'/></worldbody></mujoco>")
>>> print(result.text, end="")
<mujoco>
  <worldbody>
    <geom size="0.1"/>
  </worldbody>
</mujoco>
>>> result.changed, result.proof, result.differences
(True, 'compiled', ())
"""

from __future__ import annotations

import os
from collections.abc import Callable
from pathlib import Path
from typing import Any, Literal

import attrs

from mjcf_model.errors import MjcfCompileError, unreadable_file
from mjcf_model.tools.check import standing_path, text_folder, written_differences
from mjcf_model.tools.diff import changes_between

__all__ = ["Formatted", "Proof", "format_file", "format_text"]

#: How a rewrite was shown to change nothing (``"unchanged"``: it is the same text).
Proof = Literal["unchanged", "compiled", "elements"]


@attrs.frozen(kw_only=True)
class Formatted:
    """The canonical form of one file and how it was checked."""

    #: The file (``"<stdin>"`` or ``"<string>"`` for text).
    path: str
    #: The text as it was.
    original: str
    #: The text in canonical form.
    text: str
    #: How the rewrite was shown to change nothing.
    proof: Proof
    #: What would change (``MjModel`` fields, or element changes); empty when safe.
    differences: tuple[str, ...] = ()

    @property
    def changed(self) -> bool:
        """Whether the canonical form differs from the text as it was."""
        return self.text != self.original

    @property
    def safe(self) -> bool:
        """Whether the rewrite may be written: it compiles (or reads) to the same model."""
        return not self.differences


def format_file(path: str | os.PathLike[str]) -> Formatted:
    r"""The canonical form of the MJCF file ``path``, checked against the original.

    Relative files (meshes, includes) resolve from the file's folder, as MuJoCo
    resolves them; the file itself is not written.

    Raises:
        MjcfError: The file cannot be read or is not MJCF (the message names file and line).

    Example:
        >>> import pathlib, tempfile
        >>> path = pathlib.Path(tempfile.mkdtemp()) / "m.xml"
        >>> _ = path.write_text('<mujoco model="m"/>\n')
        >>> format_file(path).changed
        False

    """
    import mujoco

    source = Path(path)
    try:
        data = source.read_bytes()
    except OSError as error:
        raise unreadable_file(source, error) from None
    return _formatted(data, str(source), lambda: mujoco.MjModel.from_xml_path(str(source)))


def format_text(text: str | bytes, *, filename: str = "<string>") -> Formatted:
    r"""The canonical form of MJCF ``text``, read as if it were the file ``filename``.

    Relative files resolve from the folder of ``filename`` (the working folder for
    ``"<string>"`` or ``"<stdin>"``).

    Raises:
        MjcfError: ``text`` is not MJCF (the message names the line).

    Example:
        >>> result = format_text('<mujoco model="m"/>\n')
        >>> result.changed, result.proof
        (False, 'unchanged')

    """
    decoded = text if isinstance(text, str) else text.decode("utf-8", errors="replace")
    return _formatted(text, filename, lambda: _compiled_text(decoded, standing_path(filename)))


def _formatted(data: str | bytes, filename: str, compile_original: Callable[[], Any]) -> Formatted:
    """The canonical form of ``data`` read as ``filename``, and its proof."""
    from serializers import dumps, loads

    text = data if isinstance(data, str) else data.decode("utf-8", errors="replace")
    folder = text_folder(filename)
    model = loads(data, base_dir=folder, filename=filename)
    canonical = dumps(model, canonical=True)
    unchanged = Formatted(path=filename, original=text, text=canonical, proof="unchanged")
    if canonical == text:
        return unchanged
    try:
        original = compile_original()
    except ValueError:  # MuJoCo rejects the original itself: compare the elements
        changes = changes_between(model, loads(canonical, base_dir=folder, filename=filename))
        return attrs.evolve(unchanged, proof="elements", differences=tuple(map(str, changes)))
    try:
        fields = written_differences(original, canonical, standing_path(filename))
    except MjcfCompileError as error:
        fields = (str(error),)
    return attrs.evolve(unchanged, proof="compiled", differences=fields)


def _compiled_text(text: str, beside: str) -> Any:
    """MuJoCo's model of ``text`` standing at ``beside`` (raises ``ValueError`` if rejected).

    The text is written beside it for the moment or, where that folder cannot be
    written, compiled from memory.
    """
    import mujoco

    from mjcf_model.tools.compare import compile_text_beside

    try:
        return compile_text_beside(text, beside)
    except OSError:
        return mujoco.MjModel.from_xml_string(text)
