"""The round-trip check behind ``mjcf-model check``: load, write, compile both, compare.

>>> import pathlib, tempfile
>>> path = pathlib.Path(tempfile.mkdtemp()) / "m.xml"
>>> _ = path.write_text("<mujoco><worldbody><geom size='0.1'/></worldbody></mujoco>")
>>> result = check_file(path)
>>> result.status, result.differences
('identical', ())
"""

from __future__ import annotations

import functools
import os
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any, Literal

import attrs

from mjcf_model.bridge.compare import model_differences, path_fields
from mjcf_model.bridge.compile_errors import Complaint
from mjcf_model.bridge.compiling import compiled
from mjcf_model.errors import (
    MjcfCompileError,
    MjcfError,
    MjcfFileError,
    MjcfSyntaxError,
    folder_advice,
)
from mjcf_model.serializers import dumps, load, loads
from mjcf_model.tools.diff import changes_between
from mjcf_model.values.encoding import escaped_bytes, for_mujoco

if TYPE_CHECKING:
    from mjcf_model.nodes.root import Mujoco

__all__ = [
    "CheckResult",
    "check_file",
    "check_text",
    "includers_of",
    "standing_path",
    "text_folder",
    "written_changes",
    "written_differences",
]

#: ``identical``: both compile to the same model; ``different``: they compile to
#: different models; ``not-compiled``: MuJoCo rejects the original itself;
#: ``part``: a file for ``<include>``, not a model alone: it reads back to the same
#: elements, and the files that include it compile; ``error``: mjcf-model could not
#: read or write it, or the round trip does not compile.
Status = Literal["identical", "different", "not-compiled", "part", "error"]


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
    #: What the user should know of a file that round-trips: bytes that are not UTF-8.
    warnings: tuple[str, ...] = ()

    @property
    def ok(self) -> bool:
        """Whether the round trip compiled to the identical model (or a part read back the same)."""
        return self.status in ("identical", "part")


def check_file(
    path: str | os.PathLike[str],
    *,
    inline_includes: bool = False,
    part: bool = False,
    stage: Callable[[str], object] | None = None,
) -> CheckResult:
    """Round-trip one MJCF file and compare the compiled models.

    Loads the file, writes it back to text, compiles the original and, in
    memory (:func:`mjcf_model.compiled`), the written text read as if it stood
    in the original's folder, and compares every field of the two ``MjModel``
    objects but the recorded file paths (:func:`mjcf_model.bridge.compare.path_fields`).

    A file MuJoCo rejects that other files include (:func:`includers_of`), or any
    file when ``part`` is true, is checked as a part for ``<include>``: it must read
    back to the same elements, and every file found including it must compile.

    ``stage`` is told each step as it begins (``"compiling the original with MuJoCo"``...):
    on a big model, MuJoCo's two compiles take most of the time (a 10,000-body model:
    14 s each here, against 2 s for the rest).

    Examples:
        >>> check_file("/no/such/file.xml").status
        'error'

    """
    import mujoco

    name = str(path)
    if not Path(path).is_file():
        if not name:
            message = "no file given: the path is empty"
        elif Path(path).is_dir():
            message = f"a folder, not a file; {folder_advice(name)}"
        else:
            message = "no such file"
        return CheckResult(path=name, status="error", message=message)
    if part:
        return _checked_part(Path(path), includers_of(Path(path)))
    result = _checked(
        name,
        lambda: mujoco.MjModel.from_xml_path(name),
        lambda: load(path, inline_includes=inline_includes),
        stage=stage,
    )
    if result.status == "not-compiled":
        includers = includers_of(Path(path))
        if includers:
            return _checked_part(Path(path), includers)
    return result


#: How far up from a file :func:`includers_of` looks for the files that include it.
INCLUDER_LEVELS = 2
#: Files larger than this are not read when looking for includers.
_INCLUDER_SIZE = 4 << 20


def _included_files(data: bytes) -> list[str]:
    r"""The ``file`` of each ``<include>`` start tag in ``data`` (a plain scan, linear).

    Examples:
        >>> _included_files(b'<mujoco><include file="a.xml"/><include  file = \'b.xml\'/>')
        ['a.xml', 'b.xml']

    """
    found = []
    position = 0
    while (start := data.find(b"<include", position)) >= 0:
        end = data.find(b">", start)
        if end < 0:
            break
        tag = data[start:end]
        position = end
        at = tag.find(b"file")
        equals = tag.find(b"=", at)
        if at < 0 or equals < 0 or tag[at + 4 : equals].strip():
            continue
        value = tag[equals + 1 :].lstrip()
        if value[:1] not in (b'"', b"'") or value.find(value[:1], 1) < 0:
            continue
        found.append(value[1 : value.find(value[:1], 1)].decode("utf-8", errors="replace"))
    return found


def includers_of(path: Path) -> list[Path]:
    """The XML files that ``<include>`` ``path``: in its folder and up to two above it.

    An include's file is looked for as MuJoCo looks: beside the including file
    (which, for the main model, is where MuJoCo looks first).

    Examples:
        >>> import pathlib, tempfile
        >>> folder = pathlib.Path(tempfile.mkdtemp())
        >>> _ = (folder / "parts").mkdir(), (folder / "parts" / "arm.xml").write_text("<mujoco/>")
        >>> scene = '<mujoco><include file="parts/arm.xml"/></mujoco>'
        >>> _ = (folder / "scene.xml").write_text(scene)
        >>> [p.name for p in includers_of(folder / "parts" / "arm.xml")]
        ['scene.xml']

    """
    target = path.resolve()
    found: list[Path] = []
    folder = target.parent
    for _ in range(INCLUDER_LEVELS + 1):
        for candidate in sorted(folder.glob("*.xml")):
            if candidate.resolve() == target or not candidate.is_file():
                continue
            try:
                if candidate.stat().st_size > _INCLUDER_SIZE:
                    continue
                data = candidate.read_bytes()
            except OSError:
                continue
            for named in _included_files(data):
                if (candidate.parent / named).resolve() == target:
                    found.append(candidate)
                    break
        if folder.parent == folder:
            break
        folder = folder.parent
    return found


def _checked_part(path: Path, includers: list[Path]) -> CheckResult:
    """A part for ``<include>``: it reads back the same, and the files including it compile."""
    import mujoco

    name = str(path)
    try:
        model = load(path)
        changes = written_changes(model, dumps(model), name)
    except MjcfError as error:
        return CheckResult(path=name, status="error", message=str(error))
    if changes:
        return CheckResult(path=name, status="different", differences=changes)
    for includer in includers:
        try:
            mujoco.MjModel.from_xml_path(str(includer))
        except ValueError as error:
            message = _rejection(str(error), functools.partial(load, includer))
            return CheckResult(
                path=name, status="not-compiled", message=f"included by {includer}: {message}"
            )
    if not includers:
        message = "a part for <include>: it reads back the same; no file including it was found"
    else:
        message = "a part for <include>, included by " + ", ".join(map(str, includers))
    return CheckResult(path=name, status="part", message=message)


def check_text(text: str, *, filename: str = "<stdin>") -> CheckResult:
    """:func:`check_file` for MJCF text read as the file ``filename`` (see :func:`text_folder`).

    Examples:
        >>> check_text("<mujoco><worldbody><geom size='1'/></worldbody></mujoco>").status
        'identical'

    """
    import mujoco

    return _checked(
        filename,
        lambda: mujoco.MjModel.from_xml_string(for_mujoco(text)),
        lambda: loads(text, base_dir=text_folder(filename), filename=filename),
        beside=standing_path(filename),
    )


def text_folder(filename: str) -> Path:
    """Where relative files resolve from for text read as ``filename``.

    The file's folder; the working folder for ``"<stdin>"`` and other names in ``<>``.

    Examples:
        >>> text_folder("robots/arm.xml"), text_folder("<stdin>") == Path.cwd()
        (PosixPath('robots'), True)

    """
    return Path(filename).parent if not filename.startswith("<") else Path.cwd()


def standing_path(filename: str) -> str:
    """A file in :func:`text_folder` that stands for ``filename`` (``stdin.xml`` for text)."""
    name = Path(filename).name if not filename.startswith("<") else "stdin.xml"
    return str(text_folder(filename) / name)


def _checked(
    name: str,
    original: Callable[[], Any],
    loaded: Callable[[], Mujoco],
    beside: str | None = None,
    stage: Callable[[str], object] | None = None,
) -> CheckResult:
    """Compile ``original()``, write ``loaded()`` back, compile that, compare."""
    told = stage or (lambda _: None)
    told("compiling the original with MuJoCo")
    try:
        model = original()
    except ValueError as error:
        return CheckResult(path=name, status="not-compiled", message=_rejection(str(error), loaded))
    try:
        told("reading it and writing it back")
        written = dumps(loaded())
        told("compiling the written model with MuJoCo and comparing")
        differences = written_differences(model, written, beside or name)
    except MjcfError as error:
        return CheckResult(path=name, status="error", message=str(error))
    status: Status = "different" if differences else "identical"
    warnings = (_not_utf8(written),) if escaped_bytes(written) else ()
    return CheckResult(path=name, status=status, differences=differences, warnings=warnings)


def _not_utf8(text: str) -> str:
    r"""The warning for ``text`` read from bytes that are not UTF-8 (Latin-1, say).

    Examples:
        >>> print(_not_utf8('<mujoco>\n<!-- caf\udce9 \udce8 -->\n</mujoco>'))  # doctest: +ELLIPSIS
        line 2: 2 bytes that are not UTF-8 (0xE9 0xE8): MuJoCo reads them as they are, ...

    """
    found = escaped_bytes(text)
    first = text.index(chr(0xDC00 + found[0]))
    shown = " ".join(f"0x{byte:02X}" for byte in found[:8]) + (" ..." if len(found) > 8 else "")
    count = f"{len(found)} bytes" if len(found) > 1 else "a byte"
    return (
        f"line {text.count(chr(10), 0, first) + 1}: {count} that are not UTF-8 ({shown}): "
        "MuJoCo reads them as they are, and mjcf-model writes them back as they were, but "
        "other XML tools refuse the file; save it as UTF-8 (a Latin-1 file: "
        "iconv -f latin1 -t utf-8)"
    )


def _rejection(message: str, loaded: Callable[[], Mujoco]) -> str:
    """MuJoCo's ``message``, after the file, line and element path of what it rejects.

    MuJoCo names a line of the file it read (of an included file: line 0); the
    model mjcf-model reads is compiled again, so that the error names the file,
    line and element path (:func:`mjcf_model.compiled`), if MuJoCo says the same of it.
    """
    plain = f"MuJoCo rejects the model: {message.strip()}"
    try:
        compiled(loaded())
    except MjcfCompileError as error:
        return str(error) if Complaint.parse(message).what in error.detail else plain
    except (MjcfSyntaxError, MjcfFileError) as error:  # the reader's words name the place
        return error.for_command_line()
    except MjcfError:  # mjcf-model cannot read it either: MuJoCo's words alone
        return plain
    return plain


def written_changes(model: Mujoco, written: str, filename: str) -> tuple[str, ...]:
    """What ``written`` reads back as that ``model`` is not, element by element.

    The proof for a file MuJoCo does not compile alone, in the words of
    :func:`~mjcf_model.tools.diff.changes_between`. ``written`` is read as if it were
    the file ``filename`` (see :func:`text_folder`).

    Raises:
        MjcfError: ``written`` cannot be read.

    Examples:
        >>> from mjcf_model import loads
        >>> written_changes(loads("<mujoco><worldbody/></mujoco>"), "<mujoco/>", "m.xml")
        ('- /mujoco/worldbody',)

    """
    reread = loads(written, base_dir=text_folder(filename), filename=filename)
    return tuple(map(str, changes_between(model, reread)))


def written_differences(original: Any, written: str, path: str) -> tuple[str, ...]:
    """The ``MjModel`` fields in which ``written`` compiles differently from ``original``.

    ``written`` is read as if it were the file ``path`` (its relative files resolve
    from there) and compiled in memory; recorded file paths are not compared.

    Raises:
        MjcfError: ``written`` cannot be read, or does not compile (the message says so).

    Examples:
        >>> import mujoco
        >>> original = mujoco.MjModel.from_xml_string("<mujoco><worldbody/></mujoco>")
        >>> written_differences(original, "<mujoco/>", "m.xml")
        ()

    """
    reread = loads(written, base_dir=Path(path).parent, filename=path)
    try:
        again = compiled(reread)
    except MjcfError as error:
        raise type(error)(f"the written model does not compile: {error.detail}") from error
    return tuple(model_differences(original, again, ignore=path_fields()))
