"""``lint``: the mistakes MuJoCo compiles without a word, found by asking MuJoCo.

Examples:
    >>> from mjcf_model import loads
    >>> model = loads(
    ...     "<mujoco><worldbody><body><joint name='j' range='1 -1'/><geom size='1'/>"
    ...     "</body></worldbody></mujoco>"
    ... )
    >>> for finding in lint(model):
    ...     print(finding.rule, finding.path)
    R201 /mujoco/worldbody/body/joint[@name='j']

"""

from __future__ import annotations

from collections.abc import Collection

from mjcf_model.errors import MjcfValueError
from mjcf_model.nodes.root import Mujoco
from mjcf_model.tools.lint import assets, contacts, inertia, keyframes, ranges
from mjcf_model.tools.lint.findings import RULES, Finding, Rule
from mjcf_model.tools.lint.subject import Subject

__all__ = ["RULE_MODULES", "lint", "selected_rules"]

#: The modules whose rules :data:`~mjcf_model.tools.lint.findings.RULES` holds (importing
#: them registers them), one per family.
RULE_MODULES = (keyframes, ranges, inertia, contacts, assets)


def selected_rules(select: Collection[str] = (), ignore: Collection[str] = ()) -> list[Rule]:
    """The rules ``select`` picks (every rule when empty) less those ``ignore`` names.

    Each entry is a code (``K104``) or a prefix of codes (``K``, ``K1``), as ruff reads
    ``--select``.

    Raises:
        MjcfValueError: An entry matches no rule (the message lists the codes).

    Examples:
        >>> [r.code for r in selected_rules(select=["K10"], ignore=["K104", "K105"])]
        ['K101', 'K102', 'K103']

    """
    for entry in (*select, *ignore):
        if not any(code.startswith(entry) for code in RULES):
            raise MjcfValueError(f"no lint rule is {entry!r}; the rules are {', '.join(RULES)}")
    return [
        rule
        for code, rule in sorted(RULES.items())
        if (not select or any(code.startswith(entry) for entry in select))
        and not any(code.startswith(entry) for entry in ignore)
    ]


def lint(
    model: Mujoco, *, select: Collection[str] = (), ignore: Collection[str] = ()
) -> list[Finding]:
    """The mistakes in ``model`` that MuJoCo compiles without a word, in rule order.

    Every rule reads MuJoCo's compile of the model (and, for contacts, MuJoCo's
    collision detection at ``qpos0`` and at each key); each finding names the file,
    line and element path and says what to do. Load a file with
    ``inline_includes=True`` so that included elements are judged with the rest.

    Args:
        model: The model to check.
        select: Rule codes or prefixes to run (all when empty).
        ignore: Rule codes or prefixes not to run.

    Raises:
        MjcfError: MuJoCo rejects the model (its error names the element), or ``select``
            or ``ignore`` names no rule.

    """
    rules = selected_rules(select, ignore)
    subject = Subject(model)
    return [finding for rule in rules for finding in rule.check(subject)]
