"""Scenes of N copies of one robot: assets shared or copied, beside ``MjSpec`` attaching.

robosuite's Panda attached N times to an empty world: ``attach_all(...,
share_assets=True)`` (each mesh, material and texture kept once), the same without
sharing (each copy's assets under its own prefix, as ``MjSpec`` attaches), and
``MjSpec`` attaching the Panda's spec N times. Each contender compiles its scene; the
notes give the compiled model's size (``MjModel.nbuffer``) and its mesh count.
"""

from __future__ import annotations

from benchmarks.harness import OURS, Case, Contender

__all__ = ["COPIES", "sharing_cases"]

#: The numbers of copies a whole run measures.
COPIES = (1, 2, 5, 10)


def sharing_cases(copies: tuple[int, ...]) -> list[Case]:
    """One case per count of Pandas: compile the shared, the unshared and ``MjSpec``'s scene."""
    from pathlib import Path

    import mujoco

    from mjcf_model import attach_all, compiled, load, loads
    from mjcf_model.compat.assets import assets_root

    path = Path(assets_root()) / "robots/panda/robot.xml"
    panda = load(path, inline_includes=True)

    def scene(count: int, share: bool) -> object:
        parts = [(panda, f"p{i}_") for i in range(count)]
        return attach_all(loads("<mujoco/>"), parts, share_assets=share)

    def by_spec(count: int) -> mujoco.MjModel:
        parent = mujoco.MjSpec()
        for index in range(count):
            child = mujoco.MjSpec.from_file(str(path))
            parent.attach(child, prefix=f"p{index}_", frame=parent.worldbody.add_frame())
        return parent.compile()

    def size(model: mujoco.MjModel) -> str:
        return f"{model.nbuffer / 1e6:.1f} MB compiled, {model.nmesh} meshes"

    cases = []
    for count in copies:
        shared, copied = scene(count, True), scene(count, False)
        cases.append(
            Case(
                f"shared assets: {count} Pandas, compile",
                [
                    Contender(
                        OURS, lambda s=shared: compiled(s), note=f"shared: {size(compiled(shared))}"
                    ),
                    Contender(
                        "mjcf-model, unshared",
                        lambda c=copied: compiled(c),
                        note=f"copied: {size(compiled(copied))}",
                    ),
                    Contender(
                        "MjSpec attach",
                        lambda n=count: by_spec(n),
                        note=f"attached: {size(by_spec(count))}",
                    ),
                ],
                f"robosuite's Panda x {count}",
            )
        )
    return cases
