"""Cases on a synthetic model of many bodies (deep chains and a wide world)."""

from __future__ import annotations

import xml.etree.ElementTree as ET

from benchmarks.etree_path import robosuite_scaled, robosuite_utils, scale_contenders
from benchmarks.harness import OURS, Case, Contender
from benchmarks.inputs import synthetic_xml

__all__ = ["synthetic_cases"]


def synthetic_cases(bodies: int) -> list[Case]:
    """Load, prefix, scale, dump, dicts, ``==`` and ``hash`` of a ``bodies``-body model."""
    import lxml.etree

    from mjcf_model import prefixed, scaled
    from mjcf_model.serializers import dumps, from_dict, loads, to_dict

    robosuite = robosuite_utils() is not None
    cases = []
    for shape in ("deep", "wide"):
        text = synthetic_xml(bodies, shape)
        model, twin = loads(text), loads(text)
        tree = ET.fromstring(text)
        data = to_dict(model)
        inputs = f"{bodies} bodies, {shape}"
        name = f"synthetic {shape}"
        cases += [
            Case(
                f"{name}: load + dump",
                [
                    Contender(OURS, lambda text=text: dumps(loads(text))),
                    Contender(
                        "ElementTree fromstring + tostring",
                        lambda text=text: ET.tostring(ET.fromstring(text), encoding="unicode"),
                    ),
                    Contender(
                        "lxml fromstring + tostring",
                        lambda text=text: lxml.etree.tostring(lxml.etree.fromstring(text)),
                    ),
                ],
                inputs,
            ),
            Case(f"{name}: load", [Contender(OURS, lambda text=text: loads(text))], inputs),
            Case(f"{name}: dump", [Contender(OURS, lambda m=model: dumps(m))], inputs),
            Case(f"{name}: prefix", [Contender(OURS, lambda m=model: prefixed(m, "p_"))], inputs),
            Case(
                f"{name}: uniform scale",
                scale_contenders(
                    lambda m=model: scaled(m, 2),
                    (lambda t=tree: robosuite_scaled(t)) if robosuite else None,
                ),
                inputs,
            ),
            Case(f"{name}: to_dict", [Contender(OURS, lambda m=model: to_dict(m))], inputs),
            Case(f"{name}: from_dict", [Contender(OURS, lambda d=data: from_dict(d))], inputs),
            Case(
                f"{name}: == of two separately loaded models",
                [Contender(OURS, lambda a=model, b=twin: a == b)],
                inputs,
            ),
            Case(f"{name}: hash", [Contender(OURS, lambda m=twin: hash(m))], inputs),
        ]
    return cases
