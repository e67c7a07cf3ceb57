"""One small MJCF model per reference row of the namespace table, for the prefix oracle.

:func:`reference_cases` gives, for every ``(schema key, reference attribute)`` of
:data:`mjcf_model.schema.namespaces.SCHEMA`, a model that uses that reference and
declares what it refers to. Every namespace uses names of its own (the body ``arm``,
the joint ``hinge``, the site ``shoulder``...), so a reference renamed in the wrong
namespace, or not at all, leaves MuJoCo a name it does not know.

References that exclude each other (an actuator's ``joint``, ``tendon``, ``site``
and ``body``; the ``geom`` and ``body`` pairs of a distance sensor) get a case each.
A row no MuJoCo model can use is in :data:`UNUSABLE`, with its reason and a model
showing that MuJoCo rejects it.
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path

import attrs
import mujoco

from mjcf_model.schema.namespaces import SCHEMA
from tests.conftest import printed_schema
from tests.support.schema_devices import actuator_case, sensor_case
from tests.support.schema_model import Case, model

_TORUS = (
    '<plugin plugin="mujoco.sdf.torus"><instance name="ring">'
    '<config key="radius1" value="0.2"/><config key="radius2" value="0.05"/>'
    "</instance></plugin>"
)
_DONUT = '<mesh name="donut"><plugin instance="ring"/></mesh>'
_SHEET = '<flexcomp name="sheet" type="grid" count="2 2 1" spacing="0.1 0.1 0.1" dim="2"{}/>'
_SKIN = (
    '<skin name="hide" {}vertex="0 0 0  0.1 0 0  0 0.1 0" face="0 1 2">'
    '<bone body="arm" bindpos="0 0 1" bindquat="1 0 0 0" vertid="0 1 2" vertweight="1 1 1"/>'
    "</skin>"
)
_STRAND = '<flex name="strand" dim="1" body="arm forearm" vertex="0 0 0  0 0 0" element="0 1"{}/>'
#: The corners of a cube, as the flex vertices and node bodies below place them.
_CUBE = [
    (x / 10 - 0.05, y / 10 - 0.05, z / 10 - 0.05) for x in (0, 1) for y in (0, 1) for z in (0, 1)
]
#: A flex whose vertices are interpolated from the eight corner bodies it names as nodes
#: (as MuJoCo writes a trilinear ``<flexcomp>``; MuJoCo 3.9 needs self-collision off).
_CORNERS = "".join(
    f'<body name="corner{i}" pos="{x} {y} {z}"/>' for i, (x, y, z) in enumerate(_CUBE)
)
_NODES = (
    '<flex name="block" dim="3" dof="trilinear" body="{}" vertex="{}" '
    'element="0 2 4 3 0 4 1 3 4 2 6 3 4 6 7 3 4 5 1 3 4 7 5 3" node="{}">'
    '<contact selfcollide="none"/></flex>'
).format(
    " ".join(["world"] * 8),
    "  ".join(f"{x} {y} {z}" for x, y, z in _CUBE),
    " ".join(f"corner{i}" for i in range(8)),
)
#: A strain equality needs an interpolated flex, and (since 4.0) the cell it constrains.
_STRAINED = (
    '<flexcomp name="block" type="grid" count="2 2 2" spacing="0.1 0.1 0.1" dim="3" '
    'dof="trilinear"><contact selfcollide="none"/></flexcomp>'
)
_HFIELD = '<hfield name="terrain" nrow="3" ncol="3" size="1 1 0.1 0.1"/>'
_LAYER = '<layer texture="checker" role="rgb"/>'
_WRAPPED = (
    '<spatial name="wrapped"><site site="shoulder"/><geom geom="knob" sidesite="elbow"/>'
    '<site site="wrist"/></spatial>'
)
_PART = (
    b'<mujoco model="part"><worldbody><body name="piece">'
    b'<geom name="bit" size="0.1"/></body></worldbody></mujoco>'
)
#: Objects of many types, each named in a tuple: the ``objtype`` keywords map to namespaces.
_TUPLE = "".join(
    f'<element objtype="{objtype}" objname="{objname}"/>'
    for objtype, objname in (
        ("body", "arm"),
        ("xbody", "forearm"),
        ("joint", "hinge"),
        ("geom", "upper"),
        ("site", "shoulder"),
        ("camera", "eye"),
        ("mesh", "tet"),
        ("texture", "checker"),
        ("material", "paint"),
        ("tendon", "cord"),
        ("numeric", "gain"),
    )
)


def _class(tag: str) -> str:
    """A default class ``<tag>c`` setting nothing on ``tag`` elements."""
    return f'<default class="{tag}c"><{tag}/></default>'


#: The model of each row that is not an actuator's or a sensor's.
_OTHER_CASES: dict[tuple[str, str], str] = {
    ("default/material", "texture"): model(
        default='<default class="dye"><material texture="checker"/></default>',
        asset='<material name="dyed" class="dye"/>',
    ),
    ("default/material/layer", "texture"): model(
        default=f'<default class="dye"><material>{_LAYER}</material></default>',
        asset='<material name="dyed" class="dye"/>',
    ),
    ("default/geom", "hfield"): model(
        default='<default class="ground"><geom type="hfield" hfield="terrain"/></default>',
        asset=_HFIELD,
        world='<geom name="floor" class="ground"/>',
    ),
    ("default/geom", "material"): model(
        default='<default class="dye"><geom material="paint"/></default>',
        world='<geom name="dyed" class="dye" size="0.1"/>',
    ),
    ("default/geom", "mesh"): model(
        default='<default class="shape"><geom type="mesh" mesh="tet"/></default>',
        world='<geom name="shaped" class="shape"/>',
    ),
    ("default/site", "material"): model(
        default='<default class="dye"><site material="paint"/></default>',
        world='<site name="dyed" class="dye"/>',
    ),
    ("default/site", "mesh"): model(
        default='<default class="shape"><site type="mesh" mesh="tet"/></default>',
        world='<site name="shaped" class="shape"/>',
    ),
    ("default/tendon", "material"): model(
        default='<default class="dye"><tendon material="paint"/></default>',
        tendon='<spatial name="dyed" class="dye"><site site="shoulder"/><site site="elbow"/>'
        "</spatial>",
    ),
    ("asset/mesh", "class"): model(
        default=_class("mesh"),
        asset='<mesh name="classy" class="meshc" vertex="0 0 0  1 0 0  0 1 0  0 0 1"/>',
    ),
    ("asset/mesh", "material"): model(
        asset='<mesh name="dyed" material="paint" vertex="0 0 0  1 0 0  0 1 0  0 0 1"/>',
        world='<geom name="shaped" type="mesh" mesh="dyed"/>',
    ),
    ("asset/mesh/plugin", "instance"): model(extension=_TORUS, asset=_DONUT),
    ("asset/skin", "material"): model(asset=_SKIN.format('material="paint" ')),
    ("asset/skin/bone", "body"): model(asset=_SKIN.format("")),
    ("asset/texture", "class"): model(
        default='<default class="texturec"><texture builtin="flat"/></default>',
        asset='<texture name="plain" class="texturec" type="2d" width="4" height="4"/>',
    ),
    ("asset/material", "class"): model(
        default=_class("material"), asset='<material name="classy" class="materialc"/>'
    ),
    ("asset/material", "texture"): model(),
    ("asset/material/layer", "texture"): model(
        asset=f'<material name="layered">{_LAYER}</material>'
    ),
    ("body", "childclass"): model(world='<body name="child" childclass="cls"/>'),
    ("body/frame", "childclass"): model(
        world='<frame childclass="cls"><geom name="framed" size="0.1"/></frame>'
    ),
    ("body/joint", "class"): model(
        world='<body name="child"><joint name="classy" class="cls"/><geom size="0.1"/></body>'
    ),
    ("body/geom", "class"): model(world='<geom name="classy" class="cls" size="0.1"/>'),
    ("body/geom", "hfield"): model(asset=_HFIELD, world='<geom type="hfield" hfield="terrain"/>'),
    ("body/geom", "material"): model(world='<geom name="dyed" material="paint" size="0.1"/>'),
    ("body/geom", "mesh"): model(world='<geom name="shaped" type="mesh" mesh="tet"/>'),
    ("body/geom/plugin", "instance"): model(
        extension=_TORUS,
        asset=_DONUT,
        world='<geom name="band" type="sdf" mesh="donut"><plugin instance="ring"/></geom>',
    ),
    ("body/attach", "model"): model(
        asset='<model name="part" file="part.xml"/>',
        world='<body name="mount"><attach model="part" body="piece" prefix="x_"/></body>',
    ),
    ("body/site", "class"): model(world='<site name="classy" class="cls"/>'),
    ("body/site", "material"): model(world='<site name="dyed" material="paint"/>'),
    ("body/site", "mesh"): model(world='<site name="shaped" type="mesh" mesh="tet"/>'),
    ("body/camera", "class"): model(world='<camera name="classy" class="cls"/>'),
    ("body/camera", "target"): model(
        world='<camera name="tracker" mode="targetbody" target="forearm"/>'
    ),
    ("body/light", "class"): model(world='<light name="classy" class="cls"/>'),
    ("body/light", "target"): model(
        world='<light name="lamp" pos="0 0 3" mode="targetbody" target="forearm"/>'
    ),
    ("body/light", "texture"): model(world='<light name="lamp" texture="checker"/>'),
    ("body/flexcomp", "material"): model(world=_SHEET.format(' material="paint"')),
    ("body/flexcomp", "mesh"): model(
        world='<flexcomp name="blob" type="mesh" mesh="tet" dim="2"/>'
    ),
    ("deformable/flex", "body"): model(deformable=_STRAND.format("")),
    ("deformable/flex", "node"): model(world=_CORNERS, deformable=_NODES),
    ("deformable/flex", "material"): model(deformable=_STRAND.format(' material="paint"')),
    ("deformable/skin", "material"): model(deformable=_SKIN.format('material="paint" ')),
    ("deformable/skin/bone", "body"): model(deformable=_SKIN.format("")),
    ("contact/pair", "class"): model(contact='<pair class="cls" geom1="upper" geom2="knob"/>'),
    ("contact/pair", "geom1"): model(contact='<pair geom1="upper" geom2="knob"/>'),
    ("contact/pair", "geom2"): model(contact='<pair geom1="upper" geom2="knob"/>'),
    ("contact/exclude", "body1"): model(contact='<exclude body1="arm" body2="socket"/>'),
    ("contact/exclude", "body2"): model(contact='<exclude body1="arm" body2="socket"/>'),
    ("tendon/spatial", "class"): model(
        tendon='<spatial name="classy" class="cls"><site site="shoulder"/><site site="elbow"/>'
        "</spatial>"
    ),
    ("tendon/spatial", "material"): model(
        tendon='<spatial name="dyed" material="paint"><site site="shoulder"/>'
        '<site site="elbow"/></spatial>'
    ),
    ("tendon/spatial/site", "site"): model(),
    ("tendon/spatial/geom", "geom"): model(tendon=_WRAPPED),
    ("tendon/spatial/geom", "sidesite"): model(tendon=_WRAPPED),
    ("tendon/fixed", "class"): model(
        tendon='<fixed name="classy" class="cls"><joint joint="slider" coef="1"/></fixed>'
    ),
    ("tendon/fixed/joint", "joint"): model(),
    ("custom/tuple/element", "objname"): model(
        custom=f'<numeric name="gain" data="1"/><tuple name="things">{_TUPLE}</tuple>'
    ),
}

_EQUALITIES = {
    "connect": ('body1="arm" body2="socket" anchor="0 0 0"', 'site1="shoulder" site2="knob_site"'),
    "weld": ('body1="arm" body2="socket"', 'site1="shoulder" site2="knob_site"'),
}


def _equality(tag: str, attribute: str) -> str:
    if tag in _EQUALITIES:
        bodies, sites = _EQUALITIES[tag]
        pair = sites if attribute.startswith("site") else bodies
        sites_world = '<site name="knob_site" pos="1 0 1"/>'
        return model(world=sites_world, equality=f'<{tag} {pair} class="cls"/>')
    if tag == "flex":
        return model(world=_SHEET.format(""), equality='<flex flex="sheet" class="cls"/>')
    if tag == "flexstrain":
        return model(
            world=_STRAINED, equality='<flexstrain flex="block" cell="0 0 0" class="cls"/>'
        )
    pair = (
        'joint1="hinge" joint2="slider"' if tag == "joint" else 'tendon1="cord" tendon2="coupling"'
    )
    return model(equality=f'<{tag} {pair} class="cls"/>')


#: Whether the installed MuJoCo ships the elasticity plugins (3.9 does; 4.0 computes
#: elasticity itself): their cable is the one bundled plugin with passive forces, which
#: a body's or a flexcomp's ``<plugin>`` must have.
HAS_ELASTICITY_PLUGINS = any(Path(mujoco.PLUGINS_DIR).glob("*elasticity*"))
_CABLE = '<plugin plugin="mujoco.elasticity.cable"><instance name="stiff"/></plugin>'
_PASSIVE_PLUGIN_CASES = {
    ("body/plugin", "instance"): model(
        extension=_CABLE, world='<body name="link"><plugin instance="stiff"/></body>'
    ),
    ("body/flexcomp/plugin", "instance"): model(
        extension=_CABLE,
        world=_SHEET.format("").replace("/>", '><plugin instance="stiff"/></flexcomp>'),
    ),
}


@attrs.frozen
class Unusable:
    """A reference row no model compiles with in the installed MuJoCo, and why."""

    #: Why MuJoCo rejects every use of the row.
    reason: str
    #: A model using the row, which MuJoCo rejects.
    xml: str
    #: A fragment of MuJoCo's error message for ``xml``.
    error: str


_NOT_PASSIVE = (
    "the installed MuJoCo ships no plugin that computes passive forces (its elasticity "
    "plugins were folded into the engine in 4.0), and a {} plugin must"
)
_PID_EXTENSION = '<plugin plugin="mujoco.pid"><instance name="stiff"/></plugin>'
#: The rows without a case in the installed MuJoCo.
UNUSABLE: Mapping[str, Unusable] = (
    {}
    if HAS_ELASTICITY_PLUGINS
    else {
        f"{key} {attribute}": Unusable(
            _NOT_PASSIVE.format(key.split("/")[-2]),
            xml.replace(_CABLE, _PID_EXTENSION),
            "does not support passive forces",
        )
        for (key, attribute), xml in _PASSIVE_PLUGIN_CASES.items()
    }
)


#: Elements MuJoCo reads outside the schema it prints (every supported release has them).
_UNPRINTED = frozenset({"body/frame", "body/replicate"})


def known(key: str, attribute: str) -> bool:
    """Whether the installed MuJoCo reads ``attribute`` on ``key`` elements."""
    return key in _UNPRINTED or attribute in printed_schema().get(key, ())


def reference_rows() -> list[tuple[str, str]]:
    """Every ``(schema key, reference attribute)`` of the namespace table."""
    return [(key, attribute) for key, spec in SCHEMA.items() for attribute in spec.references]


def reference_cases() -> dict[tuple[str, str], Case]:
    """A case for every reference row that has one."""
    cases = {}
    for key, attribute in reference_rows():
        section, _, tag = key.partition("/")
        if (key, attribute) in _OTHER_CASES:
            xml = _OTHER_CASES[key, attribute]
        elif (key, attribute) in _PASSIVE_PLUGIN_CASES and HAS_ELASTICITY_PLUGINS:
            xml = _PASSIVE_PLUGIN_CASES[key, attribute]
        elif section == "actuator" and "/" not in tag:
            xml = actuator_case(tag, attribute)
        elif section == "sensor" and "/" not in tag:
            xml = sensor_case(tag, attribute)
        elif section == "equality":
            xml = _equality(tag, attribute)
        else:
            continue
        assets = {"part.xml": _PART} if key == "body/attach" else {}
        cases[key, attribute] = Case(key, attribute, xml, assets)
    return cases
