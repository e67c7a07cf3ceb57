"""Cases with robosuite-style objects: constructing them, and composing N into one world."""

from __future__ import annotations

from benchmarks.harness import OURS, Case, Contender
from benchmarks.inputs import package_dir

__all__ = ["object_cases"]

_COMPOSITE = dict(
    total_size=[0.1, 0.1, 0.05],
    geom_types=["box", "box"],
    geom_sizes=[[0.1, 0.1, 0.01], [0.01, 0.1, 0.05]],
    geom_locations=[[0, 0, 0], [0, 0, 0.02]],
)


def _compat() -> object | None:
    try:
        from mjcf_model.compat import objects
    except ImportError:
        return None
    return objects


def object_cases(sizes: tuple[int, ...]) -> list[Case]:
    """Object construction (this layer against robosuite) and composition for each N."""
    if package_dir("robosuite") is None:
        return [Case("objects", [Contender(OURS, None, "robosuite is not installed")])]
    import robosuite.models.objects as theirs
    from robosuite.models.world import MujocoWorldBase

    from mjcf_model import attach_all
    from serializers import dumps, loads

    ours = _compat()
    cases: list[Case] = []
    for label, make in (
        ("CanObject", lambda m: m.CanObject("can")),
        ("BoxObject", lambda m: m.BoxObject("box", size=[0.02, 0.02, 0.02])),
        ("CompositeObject", lambda m: m.CompositeObject("comp", **_COMPOSITE)),
    ):
        cases.append(
            Case(
                f"construct {label} (compat layer)",
                [
                    Contender(
                        OURS,
                        (lambda make=make: make(ours)) if ours else None,
                        "compat layer not available",
                    ),
                    Contender("robosuite", lambda make=make: make(theirs)),
                ],
                "one object",
            )
        )
    can = theirs.CanObject("can")
    model = loads(can.get_xml())
    for count in sizes:

        def ours_compose(count: int = count) -> str:
            return dumps(attach_all(loads("<mujoco/>"), [(model, f"o{i}_") for i in range(count)]))

        def ours_memory(count: int = count) -> object:
            return attach_all(loads("<mujoco/>"), [(model, f"o{i}_") for i in range(count)])

        def robosuite_compose(count: int = count, write: bool = True) -> object:
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
                    Contender("robosuite (CanObject + merge_assets + append)", robosuite_compose),
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
                        "robosuite", lambda count=count: robosuite_compose(count, write=False)
                    ),
                ],
                f"N = {count}",
                memory=True,
            )
        )
    return cases
