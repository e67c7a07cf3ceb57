"""Range rules (``R``): a range MuJoCo compiles but cannot use.

Under ``<compiler autolimits="true">`` (MuJoCo's default since 2.2) a range whose first
number is not below its second leaves the joint, tendon or actuator unlimited without
a word: ``limited`` is not written, so MuJoCo decides it from the range and finds
none. (With ``limited="true"`` MuJoCo refuses the model instead.)
"""

from __future__ import annotations

from collections.abc import Iterator

from mjcf_model.tools.lint.findings import Finding, rule
from mjcf_model.tools.lint.subject import Subject

__all__ = ["RANGES"]

#: Each range MuJoCo compiles: its kind of object, its attribute, the compiled array.
RANGES = (
    ("joint", "range", "jnt_range"),
    ("joint", "actuatorfrcrange", "jnt_actfrcrange"),
    ("tendon", "range", "tendon_range"),
    ("tendon", "actuatorfrcrange", "tendon_actfrcrange"),
    ("actuator", "ctrlrange", "actuator_ctrlrange"),
    ("actuator", "forcerange", "actuator_forcerange"),
    ("actuator", "actrange", "actuator_actrange"),
)


@rule(
    "R201",
    "reversed-range",
    "error",
    "a range whose first number is not below its second, which leaves it unlimited",
)
def reversed_range(subject: Subject) -> Iterator[Finding]:
    """A joint, tendon or actuator range written backwards (or empty).

    ``range="1 -1"`` under ``autolimits`` compiles to an unlimited joint; ``0 0`` is
    MuJoCo's default (no range) and is left alone.
    """
    m = subject.physics
    for kind, attribute, array in RANGES:
        values = getattr(m, array, None)
        if values is None:
            continue
        for row, (low, high) in enumerate(values):
            if low < high or (low == 0 and high == 0):
                continue
            what = "empty" if low == high else "reversed"
            yield subject.finding(
                "R201",
                (kind, row),
                f"{kind} {subject.name(kind, row)} has {attribute} {low:.6g} {high:.6g}, "
                f"which is {what}: MuJoCo compiles it as no limit at all; write the smaller "
                "number first (or remove the range)",
            )
