"""One small model per length attribute the scaling rules scale, with the compiled value to check.

Each :class:`~tests.support.scale_elements.ScaleCase` sets one attribute of one schema key on
the base model of :mod:`tests.support.schema_model`, and says where MuJoCo's compiled model
holds its value: scaling by 2 must multiply that value by ``2 ** power``.
"""

from __future__ import annotations

import numpy as np

from tests.support.scale_elements import SLIDER, ScaleCase, element_cases, of, setting, whole
from tests.support.schema_devices import ACTUATOR_SETTINGS as _ACTUATOR_SETTINGS
from tests.support.schema_model import model

#: An irregular tetrahedron (as the base model's ``tet``): no two principal inertias tie,
#: so MuJoCo's mesh frame does not turn with the rounding of a scaled copy.
_VERTICES = 'vertex="0 0 0  0.1 0 0  0.02 0.13 0  0.03 0.01 0.07"'
_SKIN = (
    '<skin name="hide" inflate="0.01" vertex="0 0 0  0.1 0 0  0 0.1 0" face="0 1 2">'
    '<bone body="arm" bindpos="0 0 1" bindquat="1 0 0 0" vertid="0 1 2" vertweight="1 1 1"/>'
    "</skin>"
)
_MOCAP = '<body name="ghost" mocap="true" pos="0 0 2"><geom size="0.1" contype="0"/></body>'
_CARRIAGE = SLIDER.format('type="slide" axis="1 0 0"')
_FIXED = (
    '<fixed name="rails" range="-0.5 0.5" springlength="0.1" margin="0.01">'
    '<joint joint="rail" coef="1"/></fixed>'
)
_SPATIAL = (
    '<spatial name="strap" range="0 2" springlength="0.5" margin="0.01" width="0.01">'
    '<site site="shoulder"/><site site="wrist"/></spatial>'
)
_SHEET = (
    '<flexcomp name="sheet" type="grid" count="2 2 1" spacing="0.1 0.1 0.1" dim="2" '
    'radius="0.01"><contact margin="0.01" gap="0.005"/></flexcomp>'
)
_STRAND = (
    '<flex name="strand" dim="1" body="arm forearm" vertex="0 0 0.1  0 0 0.1" element="0 1" '
    'radius="0.01"><contact margin="0.01" gap="0.005"/></flex>'
)
_POINTS = (
    '<flexcomp name="dots" type="direct" dim="1" point="0 0 0  0.1 0.2 0.3" element="0 1" '
    'scale="1 2 3"/>'
)
_CRANK = 'cranksite="shoulder" slidersite="wrist" cranklength="0.3"'
#: The actuators whose crank length is a length, with what else they need.
_CRANKED = {
    tag: _ACTUATOR_SETTINGS[tag]
    for tag in _ACTUATOR_SETTINGS
    if tag not in ("orientation", "plugin", "adhesion")  # no cranklength
}


def _actuator_cases() -> list[ScaleCase]:
    crank = of("actuator_cranklength", "actuator", "probe")
    cases = [
        ScaleCase(
            f"actuator/{tag}",
            "cranklength",
            model(actuator=f'<{tag} name="probe" {settings} {_CRANK}/>'),
            crank,
        )
        for tag, settings in _CRANKED.items()
    ]
    sites = 'cranksite="shoulder" slidersite="wrist"'
    cases += [
        ScaleCase(
            f"default/{tag}",
            "cranklength",
            model(
                default=f'<default class="cranks"><{tag} cranklength="0.3" '
                f"{settings if tag == 'dcmotor' else ''}/></default>",
                actuator=f'<{tag} name="probe" class="cranks" {settings} {sites}/>',
            ),
            crank,
        )
        for tag, settings in _CRANKED.items()
    ]
    plugin = (
        f'<plugin name="probe" plugin="mujoco.pid" {_CRANK}><config key="kp" value="1"/></plugin>'
    )
    gain = of("actuator_gainprm", "actuator", "probe", slice(0, 1))
    cases += [
        ScaleCase(
            "actuator/plugin",
            "cranklength",
            model(extension='<plugin plugin="mujoco.pid"/>', actuator=plugin),
            crank,
        ),
        ScaleCase(
            "actuator/position",
            "ctrlrange",
            model(
                world=_CARRIAGE,
                actuator='<position name="probe" joint="rail" kp="1" ctrlrange="-0.5 0.5"/>',
            ),
            of("actuator_ctrlrange", "actuator", "probe"),
        ),
    ]
    for key, attribute, text in (
        ("actuator/cylinder", "diameter", 'diameter="0.1"'),
        ("actuator/cylinder", "area", 'area="0.01"'),
    ):
        own = model(actuator=f'<cylinder name="probe" joint="hinge" {text}/>')
        classed = model(
            default=f'<default class="pistons"><cylinder {text}/></default>',
            actuator='<cylinder name="probe" class="pistons" joint="hinge"/>',
        )
        cases += [
            ScaleCase(key, attribute, own, gain, 2),
            ScaleCase(f"default/{key.split('/')[1]}", attribute, classed, gain, 2),
        ]
    return cases


#: MuJoCo keeps mesh vertices in single precision: a factor other than a power of two
#: rounds them in the 8th digit.
_SINGLE = 1e-6


def _asset_cases() -> list[ScaleCase]:
    shaped = '<geom name="shaped" type="mesh" mesh="probe"/>'
    return [
        ScaleCase(
            "asset/mesh",
            "scale",
            model(asset=f'<mesh name="probe" scale="1 2 3" {_VERTICES}/>', world=shaped),
            whole("mesh_vert"),
            rtol=_SINGLE,
        ),
        ScaleCase(
            "default/mesh",
            "scale",
            model(
                default='<default class="meshes"><mesh scale="1 2 3"/></default>',
                asset=f'<mesh name="probe" class="meshes" {_VERTICES}/>',
                world=shaped,
            ),
            whole("mesh_vert"),
            rtol=_SINGLE,
        ),
        ScaleCase(
            "asset/hfield",
            "size",
            model(
                asset='<hfield name="probe" nrow="3" ncol="3" size="1 2 0.3 0.1"/>',
                world='<geom type="hfield" hfield="probe"/>',
            ),
            of("hfield_size", "hfield", "probe"),
        ),
        *(
            ScaleCase(key, attribute, xml, whole(field))
            for section, xml in (
                ("asset", model(asset=_SKIN)),
                ("deformable", model(deformable=_SKIN)),
            )
            for key, attribute, field in (
                (f"{section}/skin", "vertex", "skin_vert"),
                (f"{section}/skin", "inflate", "skin_inflate"),
                (f"{section}/skin/bone", "bindpos", "skin_bonebindpos"),
            )
        ),
    ]


_RADII = '<config key="radius1" value="0.2"/><config key="radius2" value="0.05"/>'


def _sdf_cases() -> list[ScaleCase]:
    """A torus made by the SDF plugin: its radii are the plugin's settings, wherever written."""
    band = of("geom_rbound", "geom", "band")
    # MuJoCo rebuilds the torus by marching cubes from the scaled radii: its bounding
    # radius follows the factor to about 1e-7 (measured 4e-8 at a factor of 3)
    sdf = {"rtol": 1e-6}
    geom = '<geom name="band" type="sdf" mesh="donut"><plugin instance="ring"/></geom>'
    instance = (
        f'<plugin plugin="mujoco.sdf.torus"><instance name="ring">{_RADII}</instance></plugin>'
    )
    on_mesh = f'<mesh name="donut"><plugin plugin="mujoco.sdf.torus">{_RADII}</plugin></mesh>'
    on_geom = (
        f'<geom name="band" type="sdf" mesh="donut"><plugin plugin="mujoco.sdf.torus">{_RADII}'
        "</plugin></geom>"
    )
    plain = '<mesh name="donut"><plugin plugin="mujoco.sdf.torus"/></mesh>'
    geom_plain = '<geom name="band" type="sdf" mesh="donut"/>'
    return [
        ScaleCase(
            "extension/plugin/instance/config",
            "value",
            model(
                extension=instance,
                asset='<mesh name="donut"><plugin instance="ring"/></mesh>',
                world=geom,
            ),
            band,
            **sdf,
        ),
        ScaleCase(
            "asset/mesh/plugin/config",
            "value",
            model(
                extension='<plugin plugin="mujoco.sdf.torus"/>',
                asset=on_mesh,
                world='<geom name="band" type="sdf" mesh="donut"/>',
            ),
            band,
            **sdf,
        ),
        ScaleCase(
            "body/geom/plugin/config",
            "value",
            model(extension='<plugin plugin="mujoco.sdf.torus"/>', asset=plain, world=on_geom),
            band,
            **sdf,
        ),
        # radii left at the plugin's built-in values are written, scaled, as new settings
        ScaleCase(
            "asset/mesh/plugin/config",
            "key",
            model(extension='<plugin plugin="mujoco.sdf.torus"/>', asset=plain, world=geom_plain),
            band,
            **sdf,
        ),
    ]


def _body_cases() -> list[ScaleCase]:
    probe = of("body_pos", "body", "probe")
    friction = lambda compiled: np.asarray(compiled.flex_friction)[:, 1:]  # noqa: E731
    return [
        ScaleCase("body", "pos", model(world='<body name="probe" pos="0.1 0.2 0.3"/>'), probe),
        ScaleCase(
            "body/frame",
            "pos",
            model(world='<frame pos="0.1 0.2 0.3"><body name="probe"/></frame>'),
            probe,
        ),
        ScaleCase(
            "body/replicate",
            "offset",
            model(
                world='<replicate count="2" offset="0.1 0.2 0.3"><body name="probe"/></replicate>'
            ),
            whole("body_pos"),
        ),
        ScaleCase(
            "body/inertial",
            "pos",
            model(
                world='<body name="probe"><joint/><inertial pos="0.1 0.2 0.3" mass="1" '
                'diaginertia="1 1 1"/></body>'
            ),
            of("body_ipos", "body", "probe"),
        ),
        ScaleCase(
            "body/flexcomp",
            "spacing",
            model(world=_SHEET),
            lambda compiled: np.asarray(compiled.body_pos)[1:],
        ),
        ScaleCase("body/flexcomp", "radius", model(world=_SHEET), whole("flex_radius")),
        ScaleCase("body/flexcomp/contact", "margin", model(world=_SHEET), whole("flex_margin")),
        ScaleCase("body/flexcomp/contact", "gap", model(world=_SHEET), whole("flex_gap")),
        ScaleCase("body/flexcomp/contact", "friction", model(world=_SHEET), friction),
        ScaleCase(
            "body/flexcomp",
            "inertiabox",
            model(world=_SHEET),
            lambda compiled: np.asarray(compiled.body_inertia)[4:],
            2,
        ),
        ScaleCase(
            "body/flexcomp",
            "scale",
            model(world=_POINTS),
            lambda compiled: np.asarray(compiled.body_pos)[4:],
        ),
        ScaleCase(
            "body/geom",
            "density",
            model(world='<body name="probe"><joint/><geom size="0.1" density="500"/></body>'),
            of("body_mass", "body", "probe"),
            0,
        ),
        ScaleCase(
            "body/inertial",
            "diaginertia",
            model(
                world='<body name="probe"><joint/><inertial pos="0 0 0" mass="1" '
                'diaginertia="0.1 0.2 0.3"/></body>'
            ),
            of("body_inertia", "body", "probe"),
            2,
        ),
        ScaleCase("deformable/flex", "vertex", model(deformable=_STRAND), whole("flex_vert")),
        ScaleCase("deformable/flex", "radius", model(deformable=_STRAND), whole("flex_radius")),
        ScaleCase(
            "deformable/flex/contact", "margin", model(deformable=_STRAND), whole("flex_margin")
        ),
        ScaleCase("deformable/flex/contact", "gap", model(deformable=_STRAND), whole("flex_gap")),
        ScaleCase("deformable/flex/contact", "friction", model(deformable=_STRAND), friction),
        *_sdf_cases(),
    ]


def _constraint_cases() -> list[ScaleCase]:
    spatial = model(tendon=_SPATIAL)
    fixed = model(world=_CARRIAGE, tendon=_FIXED)
    cases = [
        ScaleCase(key, attribute, xml, of(field, "tendon", name))
        for key, xml, name in (
            ("tendon/spatial", spatial, "strap"),
            ("tendon/fixed", fixed, "rails"),
        )
        for attribute, field in (
            ("range", "tendon_range"),
            ("springlength", "tendon_lengthspring"),
            ("margin", "tendon_margin"),
        )
    ]
    eq = lambda compiled: np.asarray(compiled.eq_data)[0][0:3]  # noqa: E731
    pose = lambda compiled: np.asarray(compiled.eq_data)[0][3:6]  # noqa: E731
    coefficient = lambda compiled: np.asarray(compiled.eq_data)[0][0:1]  # noqa: E731
    mixed = '<fixed name="mixed"><joint joint="slider" coef="1"/><joint joint="hinge" coef="0.5"/>'
    return [
        *cases,
        # a fixed tendon over a slide joint is a length: its hinge's coef is a lever arm
        ScaleCase(
            "tendon/fixed/joint",
            "coef",
            model(tendon=f"{mixed}</fixed>"),
            lambda compiled: compiled.wrap_prm[
                compiled.tendon_adr[compiled.tendon("mixed").id] + 1
            ],
        ),
        ScaleCase(
            "equality/joint",
            "polycoef",
            model(equality='<joint joint1="slider" polycoef="0.1"/>'),
            coefficient,
        ),
        ScaleCase(
            "equality/tendon",
            "polycoef",
            model(equality='<tendon tendon1="cord" polycoef="0.1"/>'),
            coefficient,
        ),
        ScaleCase("tendon/spatial", "width", spatial, of("tendon_width", "tendon", "strap")),
        ScaleCase(
            "equality/connect",
            "anchor",
            model(equality='<connect body1="arm" body2="socket" anchor="0.1 0.2 0.3"/>'),
            eq,
        ),
        ScaleCase(
            "equality/weld",
            "anchor",
            model(equality='<weld body1="arm" body2="socket" anchor="0.1 0.2 0.3"/>'),
            eq,
        ),
        ScaleCase(  # a slide joint coupled to a hinge: every coefficient is a length
            "equality/joint",
            "polycoef",
            model(
                world=_CARRIAGE,
                equality='<joint joint1="rail" joint2="hinge" polycoef="0.1 0.2 0.3 0 0"/>',
            ),
            lambda compiled: np.asarray(compiled.eq_data)[0][0:5],
        ),
        ScaleCase(
            "equality/weld",
            "relpose",
            model(equality='<weld body1="arm" body2="socket" relpose="0.1 0.2 0.3 1 0 0 0"/>'),
            pose,
        ),
    ]


def _global_cases() -> list[ScaleCase]:
    key = '<key name="pose" qpos="0 0.3 1 0 0 0 0.2" qvel="0 0.3 0 0 0 0.2" mpos="0.1 0.2 2"/>'
    keyed = model(world=_MOCAP + _CARRIAGE, keyframe=key)
    statistic = '<statistic center="0.1 0.2 0.3" extent="2" meansize="0.1"/>'
    return [
        ScaleCase(
            "option", "o_margin", model(raw='<option o_margin="0.01"/>'), setting("opt", "o_margin")
        ),
        *(
            ScaleCase("statistic", attribute, model(raw=statistic), setting("stat", attribute))
            for attribute in ("center", "extent", "meansize")
        ),
        ScaleCase("keyframe/key", "mpos", keyed, whole("key_mpos")),
        ScaleCase("keyframe/key", "qpos", keyed, lambda c: np.asarray(c.key_qpos)[0][[1, 6]]),
        ScaleCase("keyframe/key", "qvel", keyed, lambda c: np.asarray(c.key_qvel)[0][[1, 5]]),
    ]


def scale_cases() -> list[ScaleCase]:
    """Every scaling case."""
    return [
        *element_cases(),
        *_actuator_cases(),
        *_asset_cases(),
        *_body_cases(),
        *_constraint_cases(),
        *_global_cases(),
    ]


#: The keys with a scaling rule but no case, and why.
UNCHECKED: dict[str, str] = {
    "actuator": "the section element has no attributes; its rule (crank length) never fires",
    "actuator/adhesion": "no cranklength attribute; the actuators' rule never fires on it",
    "actuator/orientation": "no cranklength attribute; the actuators' rule never fires on it",
    "compiler": "only masses and inertias, which the default mass policy keeps",
    "body/flexcomp/elasticity": "no compiled field holds thickness alone (it enters the "
    "flex stiffness with Young's modulus)",
    "deformable/flex/elasticity": "no compiled field holds thickness alone (it enters the "
    "flex stiffness with Young's modulus)",
}
