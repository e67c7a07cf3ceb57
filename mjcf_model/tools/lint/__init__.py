"""The linter: mistakes MuJoCo compiles without a word, found by asking MuJoCo.

``lint(model)`` returns :class:`Finding` objects, each naming the file, line and element
path, a rule code, a severity and what to do; ``mjcf-model lint FILE...`` prints them.
The rules (:data:`RULES`) come in families: ``K`` keyframes, ``R`` ranges, ``I``
inertia, ``P`` contacts, ``A`` assets and default classes.
"""

from __future__ import annotations

from mjcf_model.tools.lint.findings import RULES, Finding, Rule, Severity
from mjcf_model.tools.lint.linting import lint, selected_rules

__all__ = ["RULES", "Finding", "Rule", "Severity", "lint", "selected_rules"]
