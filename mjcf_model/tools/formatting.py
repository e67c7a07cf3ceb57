"""The tidy form of an MJCF file, and the proof that it compiles to the same model.

:func:`format_text` rewrites MJCF text in its tidy form (:mod:`mjcf_model.serializers.tidy`):
one element a line, indented by depth, long start tags wrapped one attribute a
line; comments, blank lines between elements, attribute order and the spelling of
every number kept (``normalize_numbers`` writes the shortest form instead). The
settings come from :class:`FormatOptions`, which ``mjcf-model fmt`` reads from
``[tool.mjcf-model]`` in ``pyproject.toml`` (:func:`options_from_pyproject`). A
rewrite is only offered with a proof that nothing changed:

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
    <geom size="0.10"/>
  </worldbody>
</mujoco>
>>> result.changed, result.proof, result.differences
(True, 'compiled', ())
>>> print(format_text("<mujoco><option timestep='0.0020'/></mujoco>",
...                   options=FormatOptions(normalize_numbers=True)).text, end="")
<mujoco>
  <option timestep="0.002"/>
</mujoco>
"""

from __future__ import annotations

import functools
import os
from collections.abc import Callable
from pathlib import Path
from typing import Any, Literal

import attrs

from mjcf_model.bridge.compare import compile_text_beside
from mjcf_model.errors import MjcfCompileError, MjcfValueError, unreadable_file
from mjcf_model.serializers import loads
from mjcf_model.serializers.tidy import DEFAULT_WIDTH, tidy_text
from mjcf_model.tools.check import (
    standing_path,
    text_folder,
    written_changes,
    written_differences,
)
from mjcf_model.tools.settings import project_settings
from mjcf_model.values.encoding import for_mujoco

__all__ = [
    "FormatOptions",
    "Formatted",
    "Proof",
    "format_file",
    "format_text",
    "options_from_pyproject",
]

#: How a rewrite was shown to change nothing (``"unchanged"``: it is the same text).
Proof = Literal["unchanged", "compiled", "elements"]


@attrs.frozen(kw_only=True)
class FormatOptions:
    """How :func:`format_text` lays a file out.

    Examples:
        >>> FormatOptions(width=120, indent=4)
        FormatOptions(width=120, indent=4, normalize_numbers=False)

    """

    #: Wrap a start tag whose line is longer than this, one attribute a line.
    width: int = attrs.field(default=DEFAULT_WIDTH, validator=attrs.validators.ge(20))
    #: Spaces per level of indentation.
    indent: int = attrs.field(default=2, validator=[attrs.validators.ge(0), attrs.validators.le(8)])
    #: Write every number in its shortest form instead of keeping its spelling.
    normalize_numbers: bool = False


#: The keys ``[tool.mjcf-model]`` in ``pyproject.toml`` may set, and the type of each.
_SETTINGS = {"width": int, "indent": int, "normalize-numbers": bool}


def options_from_pyproject(start: str | os.PathLike[str]) -> tuple[FormatOptions, Path | None]:
    r"""The options ``[tool.mjcf-model]`` sets in the ``pyproject.toml`` nearest ``start``.

    Looked for in ``start`` (a folder or file) and each folder above it, as ruff and
    black look (:func:`~mjcf_model.tools.settings.project_settings`); the defaults (and
    ``None``) when there is none.

    Raises:
        MjcfValueError: The table sets a key it may not, or a value of the wrong type
            (the message names the file).

    Examples:
        >>> import pathlib, tempfile
        >>> folder = pathlib.Path(tempfile.mkdtemp())
        >>> _ = (folder / "pyproject.toml").write_text("[tool.mjcf-model]\nwidth = 120\n")
        >>> options_from_pyproject(folder)[0].width
        120

    """
    table, candidate = project_settings(start)
    settings: dict[str, Any] = {}
    for key, value in table.items():
        if key == "lint":  # the linter's table (mjcf_model.tools.lint)
            continue
        kind = _SETTINGS.get(key)
        if kind is None or type(value) is not kind:
            expected = ", ".join(f"{k} ({t.__name__})" for k, t in _SETTINGS.items())
            raise MjcfValueError(
                f"[tool.mjcf-model] {key} = {value!r}: the settings are {expected} "
                "(and the table [tool.mjcf-model.lint])",
                file=str(candidate),
            )
        settings[key.replace("-", "_")] = value
    try:
        return FormatOptions(**settings), candidate
    except ValueError as error:
        raise MjcfValueError(f"[tool.mjcf-model]: {error}", file=str(candidate)) from None


@attrs.frozen(kw_only=True)
class Formatted:
    """The canonical form of one file and how it was checked."""

    #: The file (``"<stdin>"`` or ``"<string>"`` for text).
    path: str
    #: The text as it was.
    original: str
    #: The text in tidy form.
    text: str
    #: How the rewrite was shown to change nothing.
    proof: Proof
    #: What would change (``MjModel`` fields, or element changes); empty when safe.
    differences: tuple[str, ...] = ()

    @property
    def changed(self) -> bool:
        """Whether the tidy form differs from the text as it was."""
        return self.text != self.original

    @property
    def safe(self) -> bool:
        """Whether the rewrite may be written: it compiles (or reads) to the same model."""
        return not self.differences


def format_file(path: str | os.PathLike[str], *, options: FormatOptions | None = None) -> Formatted:
    r"""The tidy form of the MJCF file ``path``, checked against the original.

    Relative files (meshes, includes) resolve from the file's folder, as MuJoCo
    resolves them; the file itself is not written.

    Raises:
        MjcfError: The file cannot be read or is not MJCF (the message names file and line).

    Examples:
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
    compile_original = functools.partial(mujoco.MjModel.from_xml_path, str(source))
    return _formatted(data, str(source), compile_original, options or FormatOptions())


def format_text(
    text: str | bytes, *, filename: str = "<string>", options: FormatOptions | None = None
) -> Formatted:
    r"""The tidy form of MJCF ``text``, read as if it were the file ``filename``.

    Relative files resolve from the folder of ``filename`` (the working folder for
    ``"<string>"`` or ``"<stdin>"``).

    Raises:
        MjcfError: ``text`` is not MJCF (the message names the line).

    Examples:
        >>> result = format_text('<mujoco model="m"/>\n')
        >>> result.changed, result.proof
        (False, 'unchanged')

    """
    decoded = text if isinstance(text, str) else text.decode("utf-8", "surrogateescape")
    compile_original = functools.partial(_compiled_text, decoded, standing_path(filename))
    return _formatted(text, filename, compile_original, options or FormatOptions())


def _formatted(
    data: str | bytes,
    filename: str,
    compile_original: Callable[[], Any],
    options: FormatOptions,
) -> Formatted:
    """The tidy form of ``data`` read as ``filename``, and its proof."""
    text = data if isinstance(data, str) else data.decode("utf-8", "surrogateescape")
    model = loads(data, base_dir=text_folder(filename), filename=filename)
    tidy = tidy_text(
        model,
        indent=" " * options.indent,
        width=options.width,
        normalize_numbers=options.normalize_numbers,
    )
    unchanged = Formatted(path=filename, original=text, text=tidy, proof="unchanged")
    if tidy == text:
        return unchanged
    try:
        original = compile_original()
    except ValueError:  # MuJoCo rejects the original itself: compare the elements
        changes = written_changes(model, tidy, filename)
        return attrs.evolve(unchanged, proof="elements", differences=changes)
    try:
        fields = written_differences(original, tidy, standing_path(filename))
    except MjcfCompileError as error:
        fields = (str(error),)
    return attrs.evolve(unchanged, proof="compiled", differences=fields)


def _compiled_text(text: str, beside: str) -> Any:
    """MuJoCo's model of ``text`` standing at ``beside`` (raises ``ValueError`` if rejected).

    The text is written beside it for the moment or, where that folder cannot be
    written, compiled from memory.
    """
    import mujoco

    try:
        return compile_text_beside(text, beside)
    except OSError:
        return mujoco.MjModel.from_xml_string(for_mujoco(text))
