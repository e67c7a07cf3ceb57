"""The exceptions mjcf-model raises.

Every error derives from :class:`MjcfError`. Each subclass also derives from the
builtin exception that existing code already catches (``ValueError``,
``KeyError``, ``OSError``), so ``except ValueError`` keeps working.

A message says *where* (file, line and element path, as far as they are
known), *what was expected* and *what was found*:

>>> from mjcf_model import loads
>>> try:
...     loads('<mujoco><worldbody><geom pos="0 1"/><bad></worldbody></mujoco>')
... except MjcfSyntaxError as error:
...     print(error)
<string>:1: /mujoco/worldbody/bad: malformed XML: mismatched tag (column 44)

A value MuJoCo may read although its typed field cannot (``pos="0 1"``) loads
verbatim; the error comes, with the same location, when the value is used:

>>> geom = loads('<mujoco><worldbody><geom pos="0 1"/></worldbody></mujoco>').worldbody.geoms[0]
>>> try:
...     geom.pos[0]
... except MjcfValueError as error:
...     print(error.path, error.detail)
/mujoco/worldbody/geom attribute 'pos': expected 3 numbers, found 2 in '0 1' (kept verbatim: \
MuJoCo may read what mjcf-model cannot)
"""

from __future__ import annotations

import os
from typing import NamedTuple, Self

__all__ = [
    "Advice",
    "MjcfAssetError",
    "MjcfCompileError",
    "MjcfDroppedSettingWarning",
    "MjcfError",
    "MjcfFileError",
    "MjcfFileNotFoundError",
    "MjcfIncludeCycleError",
    "MjcfIncludeError",
    "MjcfLookupError",
    "MjcfRecompiledWarning",
    "MjcfRenderError",
    "MjcfSecurityError",
    "MjcfSyntaxError",
    "MjcfValueError",
    "folder_advice",
    "unreadable_file",
]


class MjcfError(Exception):
    """Root of every error raised by mjcf-model.

    Attributes:
        file: The file the problem was found in, ``"<string>"`` for text, or ``None``.
        line: The 1-based line number, or ``None`` when not known.
        path: The element path (``/mujoco/worldbody/body[@name='torso']/geom[2]``) or ``None``.
        detail: The message without the location prefix.

    """

    def __init__(
        self,
        detail: str,
        *,
        file: str | None = None,
        line: int | None = None,
        path: str | None = None,
        advice: Advice | None = None,
    ) -> None:
        self.detail = detail
        self.file = file
        self.line = line
        self.path = path
        #: What to do about it, said for Python and for the command line; ``None`` if nothing.
        self.advice = advice
        super().__init__(self._render())

    def _render(self, command_line: bool = False) -> str:
        where = ""
        if self.file is not None:
            where = self.file if self.line is None else f"{self.file}:{self.line}"
        elif self.line is not None:
            where = f"line {self.line}"
        parts = [p for p in (where, self.path) if p]
        detail = self.detail
        if self.advice is not None:
            said = self.advice.command_line if command_line else self.advice.python
            detail = f"{detail}; {said}"
        return ": ".join([*parts, detail])

    def __str__(self) -> str:
        return self._render()

    def for_command_line(self) -> str:
        """The message, its advice speaking of files and options instead of Python arguments.

        Examples:
            >>> error = MjcfValueError("no file", advice=Advice("pass assets=", "copy it here"))
            >>> str(error), error.for_command_line()
            ('no file; pass assets=', 'no file; copy it here')

        """
        return self._render(command_line=True)

    def located(
        self, *, file: str | None = None, line: int | None = None, path: str | None = None
    ) -> Self:
        """Return a copy of this error with missing location parts filled in.

        Examples:
            >>> err = MjcfValueError("bad").located(file="a.xml", line=3)
            >>> str(err)
            'a.xml:3: bad'

        """
        return type(self)(
            self.detail,
            file=self.file if self.file is not None else file,
            line=self.line if self.line is not None else line,
            path=self.path if self.path is not None else path,
            advice=self.advice,
        )


class Advice(NamedTuple):
    """What to do about an error, said twice: to a Python caller and on the command line."""

    #: Advice naming functions and their arguments (``inline_includes=True``).
    python: str
    #: The same advice in terms of files and command-line options.
    command_line: str


class MjcfSyntaxError(MjcfError, ValueError):
    """The text is not well-formed XML, or not MJCF at all (wrong root element)."""


class MjcfValueError(MjcfError, ValueError):
    """An attribute value has the wrong form: count of numbers, number syntax, keyword."""


class MjcfLookupError(MjcfError, KeyError):
    """A name, tag or attribute that was asked for does not exist; lists those that do."""

    def __str__(self) -> str:
        # KeyError would otherwise quote the message with repr().
        return self._render()


class MjcfFileError(MjcfError, OSError):
    """A file cannot be read or written; ``errno``, ``strerror`` and ``filename`` say why.

    :class:`MjcfIncludeError` and :class:`MjcfAssetError` narrow it down to the
    files a model names.
    """

    def __str__(self) -> str:
        return self._render()


class MjcfFileNotFoundError(MjcfFileError, FileNotFoundError):
    """The file to read does not exist (``except FileNotFoundError`` catches it too)."""


class MjcfIncludeError(MjcfFileError):
    """An ``<include>`` names a file that cannot be found or read."""


class MjcfIncludeCycleError(MjcfError, ValueError):
    """Files include (or, through asset ``<model>`` elements, attach) each other."""


class MjcfAssetError(MjcfFileError):
    """A file the model names cannot be read, or an exported file cannot be written.

    The files a model names are meshes, textures, height fields, skins and
    asset ``<model>`` files.
    """


def unreadable_file(path: object, error: OSError) -> MjcfFileError:
    """The error for a file given to read that cannot be: ``error``'s reason, and its kind.

    An empty path and a folder are said to be what they are.

    Examples:
        >>> try:
        ...     open("/no/such/model.xml")
        ... except OSError as error:
        ...     problem = unreadable_file("/no/such/model.xml", error)
        >>> isinstance(problem, FileNotFoundError), str(problem)
        (True, "cannot read '/no/such/model.xml': No such file or directory")
        >>> str(unreadable_file("", IsADirectoryError(21, "Is a directory")))
        'no file given: the path is empty; name the model file (scene.xml)'

    """
    kind = MjcfFileNotFoundError if isinstance(error, FileNotFoundError) else MjcfFileError
    name = os.fspath(path) if isinstance(path, (str, os.PathLike)) else str(path)
    if not name:
        detail = "no file given: the path is empty; name the model file (scene.xml)"
    elif isinstance(error, IsADirectoryError) or os.path.isdir(name):
        detail = f"{name!r} is a folder, not a file; {folder_advice(name)}"
    else:
        detail = f"cannot read {name!r}: {error.strerror or error}"
    problem = kind(detail)
    problem.errno, problem.strerror, problem.filename = error.errno, error.strerror, name
    return problem


def folder_advice(folder: str) -> str:
    """What to do with a folder given for a model file: name one of its XML files.

    Examples:
        >>> folder_advice("/no/such/folder")
        'name a model file in it'

    """
    try:
        found = sorted(entry.name for entry in os.scandir(folder) if entry.name.endswith(".xml"))
    except OSError:
        found = []
    if not found:
        return "name a model file in it"
    shown = ", ".join(os.path.join(folder, name) for name in found[:3])
    more = f" (and {len(found) - 3} more .xml files)" if len(found) > 3 else ""
    return f"name a model file in it: {shown}{more}"


class MjcfCompileError(MjcfError, ValueError):
    """MuJoCo rejects the model; the message is MuJoCo's own."""


class MjcfRenderError(MjcfError, RuntimeError):
    """MuJoCo cannot draw: no OpenGL backend works here; the message says what to install."""


class MjcfSecurityError(MjcfError, ValueError):
    """The XML declares a DTD or entities; mjcf-model never expands or fetches them."""


class MjcfDroppedSettingWarning(UserWarning):
    """A composed part's setting is dropped: the parent's ``<option>``, ``<size>``, ... hold.

    MuJoCo keeps one set of model-wide settings, so :func:`mjcf_model.attach`
    keeps the parent's and warns, naming each of the child's it drops. Filter
    it as any warning: ``warnings.simplefilter("ignore", MjcfDroppedSettingWarning)``.
    """


class MjcfRecompiledWarning(UserWarning):
    """:func:`mjcf_model.patched` compiled the model in full: a change has no one-for-one array.

    The message names the first such change. The result is still exact; only the
    time differs. Filter it as any warning.
    """
