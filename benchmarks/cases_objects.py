"""Cases with robosuite-style objects: constructing them, and composing N into one world."""

from __future__ import annotations

from typing import Any

from benchmarks.etree_path import MISSING_ROBOSUITE
from benchmarks.harness import OURS, Case, Contender

__all__ = ["object_cases"]

_COMPOSITE = dict(
    total_size=[0.1, 0.1, 0.05],
    geom_types=["box", "box"],
    geom_sizes=[[0.1, 0.1, 0.01], [0.01, 0.1, 0.05]],
    geom_locations=[[0, 0, 0], [0, 0, 0.02]],
)


#: What the "+ get_obj() + asset" rows do after constructing the object.
_TOUCHED = "then the body element and the asset element, as a task appending the object reads them"


def _touched(obj: Any) -> tuple[object, object]:
    """What robosuite users read right after constructing an object."""
    return obj.get_obj(), obj.asset


def _compat() -> Any:
    try:
        from mjcf_model.compat import objects
    except ImportError:
        return None
    return objects


def _robosuite_objects() -> Any:
    try:
        import robosuite.models.objects as objects
    except ImportError:
        return None
    return objects


def _construction_cases(ours: Any, theirs: Any) -> list[Case]:
    """Constructing one object, alone and with the elements read right after."""
    cases = []
    for label, make in (
        ("CanObject", lambda m: m.CanObject("can")),
        ("BoxObject", lambda m: m.BoxObject("box", size=[0.02, 0.02, 0.02])),
        ("CompositeObject", lambda m: m.CompositeObject("comp", **_COMPOSITE)),
    ):
        for suffix, work, note in (
            ("", make, ""),
            (" + get_obj() + asset", lambda m, make=make: _touched(make(m)), _TOUCHED),
        ):
            cases.append(
                Case(
                    f"construct {label}{suffix} (compat layer)",
                    [
                        Contender(
                            OURS,
                            (lambda work=work: work(ours)) if ours else None,
                            "compat layer not available",
                            note=note,
                        ),
                        Contender(
                            "robosuite",
                            (lambda work=work: work(theirs)) if theirs else None,
                            MISSING_ROBOSUITE,
                            note=note,
                        ),
                    ],
                    "one object",
                )
            )
    return cases


def _compose_cases(can_xml: str, theirs: Any, sizes: tuple[int, ...]) -> list[Case]:
    """Composing N cans into one world, written and (peak memory) unwritten."""
    from mjcf_model import attach_all
    from mjcf_model.serializers import dumps, loads

    model = loads(can_xml)
    cases = []
    for count in sizes:

        def ours_compose(count: int = count) -> str:
            return dumps(attach_all(loads("<mujoco/>"), [(model, f"o{i}_") for i in range(count)]))

        def ours_memory(count: int = count) -> object:
            return attach_all(loads("<mujoco/>"), [(model, f"o{i}_") for i in range(count)])

        def robosuite_compose(count: int = count, write: bool = True) -> object:
            from robosuite.models.world import MujocoWorldBase

            world = MujocoWorldBase()
            for i in range(count):
                obj = theirs.CanObject(f"o{i}")
                world.merge_assets(obj)
                world.worldbody.append(obj.get_obj())
            return world.get_xml() if write else world

        cases.append(
            Case(
                f"compose {count} cans + write XML",
                [
                    Contender(OURS, ours_compose),
                    Contender(
                        "robosuite (CanObject + merge_assets + append)",
                        robosuite_compose if theirs else None,
                        MISSING_ROBOSUITE,
                    ),
                ],
                f"N = {count}",
            )
        )
        cases.append(
            Case(
                f"compose {count} cans, before writing (peak memory)",
                [
                    Contender(OURS, ours_memory),
                    Contender(
                        "robosuite",
                        (lambda count=count: robosuite_compose(count, write=False))
                        if theirs
                        else None,
                        MISSING_ROBOSUITE,
                    ),
                ],
                f"N = {count}",
                memory=True,
            )
        )
    return cases


def object_cases(sizes: tuple[int, ...]) -> list[Case]:
    """Object construction (this layer against robosuite) and composition for each N.

    Without robosuite the robosuite rows say so; the cans composed are then the
    compat layer's (the same XML, see :mod:`mjcf_model.compat.objects`).
    """
    ours, theirs = _compat(), _robosuite_objects()
    cases = _construction_cases(ours, theirs)
    source = theirs or ours
    if source is None:
        return [*cases, Case("compose", [Contender(OURS, None, "no CanObject to compose")])]
    return [*cases, *_compose_cases(source.CanObject("can").get_xml(), theirs, sizes)]
