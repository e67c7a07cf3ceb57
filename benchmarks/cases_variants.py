"""The domain-randomisation loop: make variants of a model and compile each, beside ``MjSpec``.

Two kinds of variant, each made the same way by both contenders from the same
seeded draws (checked before timing: both compile to the same model):

* physical: every geom gets a random ``rgba`` and sliding friction, every body
  with an explicit inertial a random mass (times 0.8 to 1.2); made and compiled,
  and made and patched into the compiled model (:func:`mjcf_model.patched`);
* scaled: every length times a factor drawn from 0.8 to 1.2, masses by volume
  (:func:`mjcf_model.scaled`; the spec side scales every length itself); compiled, and
  patched into the compiled model;
* compiling: ``compiled(load(path))`` against MuJoCo loading the file.

``MjSpec`` parses the file once and copies the spec per variant (``spec.copy()``);
this library loads the file once and transforms the immutable model per variant.
"""

from __future__ import annotations

import copy
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import mujoco
import numpy as np

from benchmarks.harness import OURS, Case, Contender

__all__ = [
    "PATCHED",
    "VARIANT_MODELS",
    "compile_cases",
    "rollout",
    "sweep_cases",
    "length_coordinates",
    "our_physical_variant",
    "scaled_differences",
    "spec_physical_variant",
    "spec_scaled_variant",
    "spec_with_skins_inline",
    "variant_cases",
]

#: The contender that patches the compiled model instead of compiling each variant.
PATCHED = "patched() (mjcf-model, no compile)"

#: How many variants each timed run makes.
VARIANTS = 10
#: How many a tiny run (CI) makes: enough to run every contender's loop.
TINY_VARIANTS = 2


def _from_an_empty_cache(run: Callable[[], object], warm: bool = True) -> Callable[[], object]:
    """``run``, first called with MuJoCo's asset cache emptied.

    MuJoCo keeps decoded meshes and textures in a cache of 512 MB that stops taking
    entries when full; the runner compiles the whole corpus before these cases, which
    fills it. Each contender starts from an empty cache, as a variant loop of its own
    does: its first run decodes every file, the later ones (the median) find them. The
    first timed call also runs twice more: after decoding a big model's meshes, the
    next few compiles in a process are slower, for whichever contender comes first
    (GR1: 165, 113, 93 then 78 ms), and the median should not depend on the order.
    ``warm=False`` (a tiny run, which times nothing) leaves those two runs out.
    """
    started = False

    def fresh() -> object:
        nonlocal started
        if not started:
            import mujoco

            mujoco.mj_clearCache(mujoco.mj_getCache())
            started = True
            if warm:
                run()
                run()
        return run()

    return fresh


def _physical_draws(rng: np.random.Generator, geoms: int, bodies: int) -> tuple[Any, Any, Any]:
    """Per geom an rgba and a sliding friction, per body with an inertial a mass factor."""
    rgba = np.column_stack([rng.uniform(0, 1, (geoms, 3)), np.ones(geoms)])
    return rgba, rng.uniform(0.5, 1.5, geoms), rng.uniform(0.8, 1.2, bodies)


def _spec_bodies(body: Any) -> Iterator[Any]:
    """A spec body and every body below it, each before its children."""
    yield body
    for child in body.bodies:
        yield from _spec_bodies(child)


def spec_physical_variant(spec: Any, rng: np.random.Generator) -> Any:
    """A copy of ``spec`` with the physical draws written, body by body (its geoms first)."""
    variant = spec.copy()
    bodies = list(_spec_bodies(variant.worldbody))
    geoms = [geom for body in bodies for geom in body.geoms]
    weighed = [body for body in bodies if body.explicitinertial]
    rgba, friction, mass = _physical_draws(rng, len(geoms), len(weighed))
    for geom, color, slide in zip(geoms, rgba, friction, strict=True):
        geom.rgba = color
        geom.friction = [slide, 0.005, 0.0001]
    for body, factor in zip(weighed, mass, strict=True):
        body.mass = body.mass * factor
    return variant


def _our_bodies(body: Any) -> Iterator[Any]:
    yield body
    for child in body.children:
        if getattr(child, "tag", None) == "body":
            yield from _our_bodies(child)


def _inertial(body: Any) -> Any:
    return next((c for c in body.children if getattr(c, "tag", None) == "inertial"), None)


def our_physical_variant(model: Any, rng: np.random.Generator) -> Any:
    """``model`` with the physical draws written, in :func:`spec_physical_variant`'s order."""
    from mjcf_model import get_attribute, with_attributes
    from mjcf_model.tree.traversal import with_children

    worldbody = model.worldbody
    bodies = list(_our_bodies(worldbody))
    geoms = [c for b in bodies for c in b.children if getattr(c, "tag", None) == "geom"]
    weighed = [b for b in bodies if _inertial(b) is not None]
    rgba, friction, mass = _physical_draws(rng, len(geoms), len(weighed))
    colors = {
        id(g): (tuple(c), (float(f), 0.005, 0.0001))
        for g, c, f in zip(geoms, rgba, friction, strict=True)
    }
    factors = dict(zip((id(b) for b in weighed), mass, strict=True))

    def rebuilt(body: Any) -> Any:
        children = []
        for child in body.children:
            tag = getattr(child, "tag", None)
            if tag == "geom":
                color, slide = colors[id(child)]
                child = with_attributes(child, {"rgba": color, "friction": slide})
            elif tag == "inertial" and id(body) in factors:
                mass_value = float(get_attribute(child, "mass")) * factors[id(body)]
                child = with_attributes(child, {"mass": mass_value})
            elif tag == "body":
                child = rebuilt(child)
            children.append(child)
        return with_children(body, children)

    return with_children(model, [rebuilt(c) if c is worldbody else c for c in model.children])


def spec_with_skins_inline(spec: Any) -> Any:
    """``spec`` with each skin read from a file written inline, as compiled once.

    A skin file's vertices and bind positions are lengths; a spec cannot scale what it
    has not read, so the loop's setup (done once, not timed) writes them into the spec,
    as :func:`mjcf_model.scaled` writes a loaded model's skin files inline.
    """
    # Compiled apart: on MuJoCo 3.9, a copy of a spec that was compiled compiles a changed
    # mesh scale to other mesh sizes than the same model read from text.
    model = spec.copy().compile()
    spec = spec.copy()
    for index, skin in enumerate(spec.skins):
        if not skin.file:
            continue
        vert, face = model.skin_vertadr[index], model.skin_faceadr[index]
        skin.file = ""
        skin.vert = model.skin_vert[vert : vert + model.skin_vertnum[index]].ravel().tolist()
        skin.face = model.skin_face[face : face + model.skin_facenum[index]].ravel().tolist()
        texcoord = model.skin_texcoordadr[index]
        if texcoord >= 0:
            count = model.skin_vertnum[index]
            skin.texcoord = model.skin_texcoord[texcoord : texcoord + count].ravel().tolist()
        first, count = model.skin_boneadr[index], model.skin_bonenum[index]
        bones = range(first, first + count)
        body_ids = model.skin_bonebodyid[first : first + count]
        skin.bodyname = [mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_BODY, b) for b in body_ids]
        skin.bindpos = model.skin_bonebindpos[bones].ravel().tolist()
        skin.bindquat = model.skin_bonebindquat[bones].ravel().tolist()
        ids, weights = [], []
        for bone in bones:
            at, n = model.skin_bonevertadr[bone], model.skin_bonevertnum[bone]
            ids.append(model.skin_bonevertid[at : at + n].tolist())
            weights.append(model.skin_bonevertweight[at : at + n].tolist())
        skin.vertid, skin.vertweight = ids, weights
    return spec


def length_coordinates(model: Any) -> tuple[int, ...]:
    """Where ``qpos`` holds lengths: free joints' positions and slide joints."""
    found: list[int] = []
    for joint in range(model.njnt):
        at, kind = int(model.jnt_qposadr[joint]), model.jnt_type[joint]
        if kind == mujoco.mjtJoint.mjJNT_FREE:
            found += (at, at + 1, at + 2)
        elif kind == mujoco.mjtJoint.mjJNT_SLIDE:
            found.append(at)
    return tuple(found)


def spec_scaled_variant(spec: Any, factor: float, lengths: tuple[int, ...] = ()) -> Any:
    """A copy of ``spec`` with every length times ``factor`` and masses by volume.

    As careful as :func:`mjcf_model.scaled`: positions of every kind of element and
    inertial, geom and site sizes and ``fromto``, mesh ``scale``, skin vertices, camera
    ``ipd``, light ``range`` and ``bulbradius``, slide joints' ranges, references and
    margins, the torsional and rolling friction of geoms (lengths in MuJoCo), contact
    margins and gaps, spatial tendons, explicit masses and inertias, equality anchors,
    keyframe mocap positions and the ``qpos`` coordinates at ``lengths`` (see
    :func:`length_coordinates`), the statistics. ``MjSpec`` gives every element its
    default classes' values when it parses, so no class needs scaling.
    """
    variant = spec.copy()
    cube = factor * factor * factor  # the volume, as the library multiplies it
    square = factor * factor
    inertia = cube * (square + square) / 2
    for body in variant.bodies:
        body.pos = body.pos * factor
        if body.explicitinertial:
            body.ipos, body.mass = body.ipos * factor, body.mass * cube
            body.inertia, body.fullinertia = body.inertia * inertia, body.fullinertia * inertia
    for frame in variant.frames:
        frame.pos = frame.pos * factor
    for placed in (*variant.geoms, *variant.sites):
        placed.pos, placed.size = placed.pos * factor, placed.size * factor
        placed.fromto = placed.fromto * factor
    for geom in variant.geoms:
        geom.friction = geom.friction * [1.0, factor, factor]
        geom.margin, geom.gap = geom.margin * factor, geom.gap * factor
        if geom.mass > 0:
            geom.mass = geom.mass * cube
    for joint in variant.joints:
        joint.pos = joint.pos * factor
        if joint.type == mujoco.mjtJoint.mjJNT_SLIDE:
            joint.range, joint.ref = joint.range * factor, joint.ref * factor
            joint.springref, joint.margin = joint.springref * factor, joint.margin * factor
    for camera in variant.cameras:
        camera.pos, camera.ipd = camera.pos * factor, camera.ipd * factor
    for light in variant.lights:
        light.pos, light.range = light.pos * factor, light.range * factor
        light.bulbradius = light.bulbradius * factor
    for mesh in variant.meshes:
        mesh.scale = mesh.scale * factor
    for skin in variant.skins:
        skin.vert = np.multiply(skin.vert, factor).tolist()
        skin.bindpos = np.multiply(skin.bindpos, factor).tolist()
    for tendon in variant.tendons:
        if all(wrap.type != mujoco.mjtWrap.mjWRAP_JOINT for wrap in tendon.path):
            tendon.range, tendon.width = tendon.range * factor, tendon.width * factor
    for key in variant.keys:
        key.mpos = np.multiply(key.mpos, factor).tolist()
        if len(key.qpos) and lengths:
            qpos = np.array(key.qpos)
            qpos[list(lengths)] *= factor
            key.qpos = qpos.tolist()
    stat = variant.stat
    stat.center, stat.extent, stat.meansize = (
        stat.center * factor,
        stat.extent * factor,
        (stat.meansize * factor),
    )
    stat.meanmass, stat.meaninertia = stat.meanmass * cube, stat.meaninertia * inertia
    variant.option.o_margin = variant.option.o_margin * factor
    return variant


#: The models of the variant loop: robosuite's mesh robots, dm_control's mesh-heavy dog
#: and mesh-free humanoid.
VARIANT_MODELS = (
    ("robosuite", "models/assets/robots/panda/robot.xml"),
    ("robosuite", "models/assets/robots/sawyer/robot.xml"),
    ("dm_control", "suite/dog.xml"),
    ("dm_control", "suite/humanoid.xml"),
)


def _variant_case(path: Path, tiny: bool) -> Case:
    count = TINY_VARIANTS if tiny else VARIANTS
    import mujoco

    from mjcf_model import compiled, patched
    from mjcf_model.bridge.compare import model_differences, path_fields
    from mjcf_model.serializers import load

    # Includes read once, as MjSpec.from_file reads them: a model that keeps its <include>
    # elements has them inlined again by every compiled() call.
    model, spec = load(path, inline_includes=True), mujoco.MjSpec.from_file(str(path))
    mine = compiled(our_physical_variant(model, np.random.default_rng(0)))
    theirs = spec_physical_variant(spec, np.random.default_rng(0)).compile()
    differences = model_differences(mine, theirs, ignore=path_fields())
    if differences:
        raise AssertionError(f"{path.name}: the two physical variants differ in {differences}")

    def ours() -> None:
        rng = np.random.default_rng(1)
        for _ in range(count):
            compiled(our_physical_variant(model, rng))

    base = compiled(model)
    scratch = copy.copy(base)

    def ours_patched() -> None:
        rng = np.random.default_rng(1)
        for _ in range(count):
            patched(base, model, our_physical_variant(model, rng), into=scratch)

    def mjspec() -> None:
        rng = np.random.default_rng(1)
        for _ in range(count):
            spec_physical_variant(spec, rng).compile()

    name = f"{path.parent.name}/{path.name}"
    return Case(
        f"physical variants: {name}",
        [
            Contender(
                OURS,
                _from_an_empty_cache(ours, not tiny),
                note="transform the loaded model, then compiled()",
            ),
            Contender(
                "MjSpec",
                _from_an_empty_cache(mjspec, not tiny),
                note="spec.copy(), the same edits, compile()",
            ),
            Contender(
                PATCHED,
                _from_an_empty_cache(ours_patched, not tiny),
                note="the same variants, patched(compiled, model, variant, into=scratch): "
                "no compile, no copy",
            ),
        ],
        f"{count} variants (rgba, friction per geom; mass per inertial)",
    )


def scaled_differences(ours: Any, theirs: Any) -> list[str]:
    """The fields two scaled variants differ in, float32 arrays compared to float32 precision.

    A spec holds some values in float32 (a light's ``bulbradius``; a skin file's data,
    which the spec side takes from a compiled model, where MuJoCo normalised the bone
    weights once already): scaled there, they round differently from the library's
    float64 product of the file's text, in the last float32 bits (within 4 ulps
    here). Every float64 array is compared exactly.
    """
    from mjcf_model.bridge.compare import model_differences, path_fields

    def close(name: str) -> bool:
        left, right = getattr(ours, name, None), getattr(theirs, name, None)
        if not isinstance(left, np.ndarray) or left.dtype != np.float32:
            return False
        return bool(np.allclose(left, right, rtol=4 * np.finfo(np.float32).eps, atol=0))

    differences = model_differences(ours, theirs, ignore=path_fields())
    return [name for name in differences if not close(name)]


def _scaled_case(path: Path, tiny: bool) -> Case:
    count = TINY_VARIANTS if tiny else VARIANTS
    from mjcf_model import compiled, patched, scaled
    from mjcf_model.serializers import load

    model = load(path, inline_includes=True)
    spec = spec_with_skins_inline(mujoco.MjSpec.from_file(str(path)))
    lengths = length_coordinates(spec.copy().compile())
    mine = compiled(scaled(model, 1.1, mass="volume"))
    differences = scaled_differences(mine, spec_scaled_variant(spec, 1.1, lengths).compile())
    if differences:
        raise AssertionError(f"{path.name}: the two scaled variants differ in {differences}")

    def ours() -> None:
        for factor in np.random.default_rng(1).uniform(0.8, 1.2, count):
            compiled(scaled(model, float(factor), mass="volume"))

    def mjspec() -> None:
        for factor in np.random.default_rng(1).uniform(0.8, 1.2, count):
            spec_scaled_variant(spec, float(factor), lengths).compile()

    base = compiled(model)
    scratch = copy.copy(base)

    def ours_patched() -> None:
        for factor in np.random.default_rng(1).uniform(0.8, 1.2, count):
            patched(base, model, scaled(model, float(factor), mass="volume"), into=scratch)

    return Case(
        f"scaled variants: {path.parent.name}/{path.name}",
        [
            Contender(
                OURS,
                _from_an_empty_cache(ours, not tiny),
                note='scaled(model, factor, mass="volume"), then compiled()',
            ),
            Contender(
                "MjSpec",
                _from_an_empty_cache(mjspec, not tiny),
                note="spec.copy(), every length scaled, compile()",
            ),
            Contender(
                PATCHED,
                _from_an_empty_cache(ours_patched, not tiny),
                note="the same variants, patched(compiled, model, variant, into=scratch): "
                "no compile (a variant patched() cannot write is compiled, with a warning)",
            ),
        ],
        f"{count} variants (uniform factor 0.8 to 1.2, masses by volume)",
    )


#: How many variants of robosuite's Panda the ``batched`` row stacks (``tiny``: the other).
BATCHED_VARIANTS, TINY_BATCHED_VARIANTS = 1000, 4
#: The case name of the ``batched`` row.
BATCHED_CASE = "batched: panda/robot.xml"


def _batched_case(path: Path, tiny: bool) -> Case:
    """``batched`` over physical variants of one model, made beforehand: its variants per second."""
    from mjcf_model import batched
    from mjcf_model.serializers import load

    model = load(path, inline_includes=True)
    rng = np.random.default_rng(2)
    count = TINY_BATCHED_VARIANTS if tiny else BATCHED_VARIANTS
    variants = [our_physical_variant(model, rng) for _ in range(count)]
    return Case(
        BATCHED_CASE,
        [
            Contender(
                OURS,
                lambda: batched(model, variants),
                note="every variant patched into one scratch model, the changed fields stacked",
            )
        ],
        f"{count} variants (rgba, friction per geom; mass per inertial), made beforehand",
    )


def variant_cases(tiny: bool = False) -> list[Case]:
    """Per model of :data:`VARIANT_MODELS` (``tiny``: the last), the physical and scaled loops.

    And the ``batched`` row, on the first model (robosuite's Panda) where it is installed.
    """
    from benchmarks.inputs import package_dir

    cases = []
    for package, relative in VARIANT_MODELS[-1:] if tiny else VARIANT_MODELS:
        folder = package_dir(package)
        if folder is not None:
            cases += (_variant_case(folder / relative, tiny), _scaled_case(folder / relative, tiny))
    package, relative = VARIANT_MODELS[0]
    folder = package_dir(package)
    if folder is not None:
        cases.append(_batched_case(folder / relative, tiny))
    return cases


def rollout(job: tuple[Any, int]) -> float:
    """The README's sweep task: one variant (masses times 0.8 to 1.2), compiled, 1 s simulated."""
    import mujoco

    from mjcf_model import compiled, map_elements, with_attributes

    model, seed = job
    rng = np.random.default_rng(seed)

    def heavier(element: Any, key: str | None, ancestors: Any) -> Any:
        if key != "body/inertial":
            return element
        return with_attributes(element, {"mass": element.mass * rng.uniform(0.8, 1.2)})

    physics = compiled(map_elements(heavier, model))
    data = mujoco.MjData(physics)
    mujoco.mj_step(physics, data, nstep=int(1 / physics.opt.timestep))
    return float(data.qpos[1])


def sweep_cases(tiny: bool = False) -> list[Case]:
    """The README's process-pool sweep on robosuite's Panda against the same jobs in one process."""
    import pickle
    from concurrent.futures import ProcessPoolExecutor

    from benchmarks.inputs import package_dir
    from mjcf_model.serializers import load

    folder = package_dir("robosuite")
    if folder is None:
        return []
    robot = load(folder / "models/assets/robots/panda/robot.xml")
    jobs = [(robot, seed) for seed in range(4 if tiny else 40)]

    def pooled() -> list[float]:
        with ProcessPoolExecutor(max_workers=2) as pool:
            return list(pool.map(rollout, jobs))

    size = len(pickle.dumps(jobs[0]))
    return [
        Case(
            "variant sweep: panda/robot.xml",
            [
                Contender(OURS, lambda: [rollout(job) for job in jobs], note="one process"),
                Contender(
                    "ProcessPoolExecutor, 2 workers",
                    pooled,
                    note=f"pool started per run; {size:,} bytes pickled per task (model, seed)",
                ),
            ],
            f"{len(jobs)} variants, each compiled and simulated for 1 s",
        )
    ]


def compile_cases(files: list[Path], most: int | None = None) -> list[Case]:
    """``compiled(load(path))`` against ``MjModel.from_xml_path`` per model with meshes.

    The two take turns (:attr:`Case.interleaved`): both spend nearly all their time in
    MuJoCo's compiler, and timed one after the other, a slow stretch of this shared
    machine fell on one of them (ratios from 0.55 to 1.82 with the same code, run to run).
    Each is timed at least 15 times and the least time is shown: both do the same work
    every run, and single compiles here now and then take twice as long (ur5e: 33 to
    63 ms in 9 runs; Fourier's hand 123 to 299 ms in 15), which a median does not always
    outvote: with the median of 15 in turns, 48 of 49 were within 1.2 in one run, 49 in
    the next.
    ``most`` keeps that many of them (a tiny run).
    """
    import mujoco

    from mjcf_model import compiled
    from mjcf_model.serializers import load

    cases: list[Case] = []
    for path in files:
        if "<mesh" not in path.read_text(errors="replace") or len(cases) == most:
            continue
        model = load(path)
        cases.append(
            Case(
                f"compile: {path.parent.name}/{path.name}",
                [
                    Contender(
                        OURS,
                        _from_an_empty_cache(lambda m=model: compiled(m), most is None),
                        note="compiled(model), loaded (its text is written at the first "
                        "compile and reused while MuJoCo reads every file by path); "
                        "the two take turns, 15 runs or more each; the least time is shown",
                    ),
                    Contender(
                        "MjModel.from_xml_path",
                        _from_an_empty_cache(
                            lambda p=str(path): mujoco.MjModel.from_xml_path(p), most is None
                        ),
                    ),
                ],
                "one mesh model",
                interleaved=True,
                least_repeat=0 if most is not None else 15,
                least=True,
            )
        )
    return cases
