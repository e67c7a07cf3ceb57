"""What the linter reports (:class:`Finding`) and the rules it checks (:class:`Rule`).

Each rule has a code (``K104``: a letter for its family, as ruff's codes have) and a
name; the rule modules register themselves in :data:`RULES` with :func:`rule`.

Examples:
    >>> finding = Finding(
    ...     file="arm.xml", line=12, path="/mujoco/keyframe/key[@name='home']",
    ...     rule="K104", severity="error", message="ctrl 0.5 ...",
    ... )
    >>> print(finding)
    arm.xml:12: /mujoco/keyframe/key[@name='home']: K104 ctrl 0.5 ...
    >>> sorted(finding.to_dict())
    ['file', 'line', 'message', 'path', 'rule', 'severity']

"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import Any, Literal

import attrs

__all__ = ["RULES", "Finding", "Rule", "Severity", "rule"]

#: How sure a finding is: ``error``, a mistake whatever the model means; ``warning``, a
#: mistake unless the model means it (say so by ignoring the rule for that file).
Severity = Literal["error", "warning"]


@attrs.frozen(kw_only=True)
class Finding:
    """One mistake the linter found, where it stands and what to do."""

    #: The file the element was read from; ``None`` for a model built in code.
    file: str | None
    #: The line of the element's start tag in that file.
    line: int | None
    #: The element path (``/mujoco/keyframe/key[@name='home']``).
    path: str | None
    #: The rule's code (``K104``).
    rule: str
    #: ``error`` or ``warning`` (see :data:`Severity`).
    severity: Severity
    #: What is wrong, what MuJoCo does with it, and what to do.
    message: str

    def __str__(self) -> str:
        place = ":".join(str(part) for part in (self.file, self.line) if part is not None)
        where = ": ".join(part for part in (place, self.path) if part)
        return f"{where}: {self.rule} {self.message}" if where else f"{self.rule} {self.message}"

    def to_dict(self) -> dict[str, Any]:
        """The finding as JSON-safe values (``mjcf-model lint --format json``)."""
        return attrs.asdict(self)


#: What a rule's check is given and gives: the model being linted (a
#: :class:`~mjcf_model.tools.lint.subject.Subject`, which imports this module), and findings.
Check = Callable[[Any], Iterable[Finding]]


@attrs.frozen(kw_only=True)
class Rule:
    """One rule: its code, name, severity, what it finds, and its check."""

    #: The code (``K104``): a letter for the family, three digits.
    code: str
    #: A name in words (``key-ctrl-servo-mismatch``).
    name: str
    #: The severity of its findings.
    severity: Severity
    #: What it finds, in one sentence (the rules page and ``lint --rules`` print it).
    summary: str
    #: The check: the findings in one model.
    check: Check = attrs.field(repr=False, eq=False)


#: Every rule, by code, in the order the rule modules register them.
RULES: dict[str, Rule] = {}


def rule(code: str, name: str, severity: Severity, summary: str) -> Callable[[Check], Check]:
    """Register the decorated check as the rule ``code``."""

    def register(check: Check) -> Check:
        if code in RULES:
            raise ValueError(f"rule {code} is registered twice")
        RULES[code] = Rule(code=code, name=name, severity=severity, summary=summary, check=check)
        return check

    return register
