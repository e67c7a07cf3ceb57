"""The namespace table: every MJCF element, its attributes, the names it declares and refers to.

The table below mirrors the schema MuJoCo prints (``mujoco.mj_printSchema``), one
element per entry, keyed by its *schema key*: the path from ``<mujoco>`` with
``worldbody`` read as ``body`` and recursion folded (a body in a body is
``body``; a geom in a body ``body/geom``; a geom in a spatial tendon
``tendon/spatial/geom``). It is the schema of MuJoCo :data:`SCHEMA_RELEASE`; a
test compares it with the installed MuJoCo (equal for that release, a superset
for an older one), so an element or attribute added by a new MuJoCo release
fails loudly.

Each attribute is written plain, or annotated:

* ``name=geom``: the attribute declares a name in the ``geom`` namespace;
* ``material>material``: it refers to a name in the ``material`` namespace;
* ``body>body*``: it holds a space-separated list of references;
* ``objname>@objtype``: the namespace is given by the value of ``objtype``.

Prefixing, reference checks and the hypothesis strategies all read this table;
typed and generic nodes alike.

>>> dict(SCHEMA["body/geom"].declares)
{'name': 'geom'}
>>> SCHEMA["actuator/motor"].references["joint"]
'joint'
>>> child_key("body", "geom"), child_key("tendon/spatial", "geom")
('body/geom', 'tendon/spatial/geom')
"""

from __future__ import annotations

from collections.abc import Mapping
from types import MappingProxyType

import attrs

__all__ = [
    "NAMESPACES",
    "OBJTYPE_NAMESPACES",
    "SCHEMA",
    "SCHEMA_RELEASE",
    "ElementSpec",
    "child_key",
    "children_context",
    "guess_context",
    "reference_namespace",
]


@attrs.frozen(kw_only=True)
class ElementSpec:
    """What the table says about one element.

    Examples:
        >>> spec = SCHEMA["contact/pair"]
        >>> sorted(spec.references.items())[:2]
        [('class', 'class'), ('geom1', 'geom')]

    """

    #: The schema key, e.g. ``"body/geom"``.
    key: str
    #: Every attribute MuJoCo accepts on this element.
    attributes: frozenset[str]
    #: Attributes that declare a name, and the namespace of that name.
    declares: Mapping[str, str]
    #: Attributes that refer to a name, and its namespace (``"@objtype"``: read it there).
    references: Mapping[str, str]
    #: The references that hold a space-separated list of names.
    list_references: frozenset[str]

    @property
    def tag(self) -> str:
        """The XML tag of the element."""
        return self.key.rsplit("/", 1)[-1]


_TABLE = """
mujoco                       model
compiler                     alignfree angle assetdir autolimits balanceinertia boundinertia
                             boundmass conflict coordinate discardvisual eulerseq fitaabb
                             fusestatic inertiafromgeom inertiagrouprange meshdir passthrough
                             savecanonical savecompiled saveinertial settotalmass strippath
                             texturedir usethread
compiler/lengthrange         accel interval inttotal maxforce mode timeconst timestep tolrange
                             useexisting uselimit
option                       actuatorgroupdisable ccd_iterations ccd_tolerance cone density gravity
                             impratio integrator iterations jacobian ls_iterations ls_tolerance
                             magnetic noslip_iterations noslip_tolerance o_friction o_margin
                             o_solimp o_solref sdf_initpoints sdf_iterations sleep_tolerance solver
                             timestep tolerance viscosity wind
option/flag                  actuation autoreset clampctrl constraint contact damper diagexact
                             energy equality eulerdamp filterparent frictionloss fwdinv gravity
                             invdiscrete ipc island limit midphase multiccd nativeccd override
                             refsafe sensor sleep speculative spring warmstart
size                         memory nconmax njmax nkey nstack nuser_actuator nuser_body nuser_cam
                             nuser_geom nuser_jnt nuser_sensor nuser_site nuser_tendon nuserdata
statistic                    center extent meaninertia meanmass meansize
visual                       -
visual/global                azimuth bvactive cameraid elevation ellipsoidinertia fovy glow ipd
                             linewidth offheight offwidth orthographic realtime
visual/quality               numquads numslices numstacks offsamples shadowsize
visual/headlight             active ambient diffuse specular
visual/map                   actuatortendon alpha fogend fogstart force haze shadowclip shadowscale
                             stiffness stiffnessrot torque zfar znear
visual/scale                 actuatorlength actuatorwidth camera com connect constraint
                             contactheight contactwidth forcewidth framelength framewidth frustum
                             jointlength jointwidth light selectpoint slidercrank
visual/rgba                  actuator actuatornegative actuatorpositive bv bvactive camera com
                             connect constraint contactforce contactfriction contactgap
                             contactpoint contacttorque crankbroken fog force frustum haze inertia
                             joint light rangefinder selectpoint slidercrank
default                      class=class
default/mesh                 inertia maxhullvert scale
default/texture              builtin colorspace embed gridlayout gridsize height hflip mark markrgb
                             nchannel random rgb1 rgb2 type vflip width
default/material             emission metallic reflectance rgba roughness shininess specular
                             texrepeat texture>texture texuniform
default/material/layer       role texture>texture
default/joint                actuatorfrclimited actuatorfrcrange actuatorgravcomp armature axis
                             damping frictionloss group limited margin pos range ref solimpfriction
                             solimplimit solreffriction solreflimit springdamper springref
                             springyield stiffness type user
default/geom                 adhesion axisangle castshadow conaffinity condim contype density euler
                             fitscale fluidcoef fluidshape friction fromto gap group hfield>hfield
                             margin mass material>material mesh>mesh pos priority quat rgba
                             shellinertia size solimp solmix solref surfacevel type user xyaxes
                             zaxis
default/site                 axisangle euler fromto group material>material mesh>mesh pos quat rgba
                             size type user xyaxes zaxis
default/camera               axisangle euler focal focalpixel fovy ipd mode output pos principal
                             principalpixel projection quat resolution sensorsize user xyaxes zaxis
default/light                active ambient attenuation bulbradius castshadow cutoff diffuse dir
                             directional exponent intensity mode pos range softness specular type
default/pair                 adhesion condim friction gap margin solimp solref solreffriction
default/equality             active solimp solref
default/tendon               actuatorfrclimited actuatorfrcrange armature damping frictionloss
                             group limited margin material>material range rgba solimpfriction
                             solimplimit solreffriction solreflimit springlength springyield
                             stiffness user width
default/general              actdim actearly actlimited actrange armature biasprm biastype
                             cranklength ctrllimited ctrlrange damping delay dynprm dyntype ffrange
                             forcelimited forcerange gainprm gaintype gear group inheritrange input
                             interp nsample user velrange
default/motor                armature cranklength ctrllimited ctrlrange damping delay forcelimited
                             forcerange gear group interp nsample user
default/position             armature cranklength ctrllimited ctrlrange damping dampratio delay
                             forcelimited forcerange gear group inheritrange interp kp kv nsample
                             timeconst user
default/velocity             armature cranklength ctrllimited ctrlrange damping delay forcelimited
                             forcerange gear group interp kv nsample user
default/intvelocity          actlimited actrange armature cranklength ctrllimited ctrlrange damping
                             dampratio delay forcelimited forcerange gear group inheritrange interp
                             kp kv nsample user
default/orientation          ctrlrange dampratio delay forcelimited forcerange group input interp
                             kp kv nsample user
default/pid                  armature cranklength ctrllimited ctrlrange damping dampratio delay
                             ffrange forcelimited forcerange gear group imax inheritrange input
                             interp ki kp kv nsample posrange slewmax user velrange
default/damper               armature cranklength ctrlrange damping delay forcelimited forcerange
                             gear group interp kv nsample user
default/cylinder             area armature bias cranklength ctrllimited ctrlrange damping delay
                             diameter forcelimited forcerange gear group interp nsample timeconst
                             user
default/muscle               armature cranklength ctrllimited ctrlrange damping delay force
                             forcelimited forcerange fpmax fvmax gear group interp lmax lmin
                             nsample range scale timeconst user vmax
default/adhesion             ctrlrange delay forcelimited forcerange gain group interp nsample user
default/dcmotor              armature cogging controller cranklength ctrllimited ctrlrange damping
                             delay gear group inductance input interp lugre motorconst nominal
                             nsample resistance saturation thermal user
extension                    -
extension/plugin             plugin
extension/plugin/instance    name=plugin
extension/plugin/instance/config key value
asset                        -
asset/mesh                   builtin class>class content_type face file inertia material>material
                             maxhullvert name=mesh normal params refpos refquat scale smoothnormal
                             texcoord vertex
asset/mesh/plugin            instance>plugin plugin
asset/mesh/plugin/config     key value
asset/hfield                 content_type elevation file name=hfield ncol nrow size
asset/skin                   face file group inflate material>material name=skin rgba texcoord
                             vertex
asset/skin/bone              bindpos bindquat body>body vertid vertweight
asset/texture                builtin class>class colorspace content_type embed file fileback
                             filedown filefront fileleft fileright fileup gridlayout gridsize
                             height hflip mark markrgb name=texture nchannel random rgb1 rgb2 type
                             vflip width
asset/material               class>class emission metallic name=material reflectance rgba roughness
                             shininess specular texrepeat texture>texture texuniform
asset/material/layer         role texture>texture
asset/model                  content_type file name=model
body                         axisangle childclass>class euler fuse gravcomp mocap name=body pos
                             quat simple sleep user xyaxes zaxis
body/inertial                axisangle diaginertia euler fullinertia mass pos quat xyaxes zaxis
body/joint                   actuatorfrclimited actuatorfrcrange actuatorgravcomp armature axis
                             class>class damping frictionloss group limited margin name=joint pos
                             range ref solimpfriction solimplimit solreffriction solreflimit
                             springdamper springref springyield stiffness type user
body/freejoint               align group name=joint
body/geom                    adhesion axisangle castshadow class>class conaffinity condim contype
                             density euler fitscale fluidcoef fluidshape friction fromto gap group
                             hfield>hfield margin mass material>material mesh>mesh name=geom pos
                             priority quat rgba shellinertia size solimp solmix solref surfacevel
                             type user xyaxes zaxis
body/geom/plugin             instance>plugin plugin
body/geom/plugin/config      key value
body/attach                  body frame model>model prefix
body/site                    axisangle class>class euler fromto group material>material mesh>mesh
                             name=site pos quat rgba size type user xyaxes zaxis
body/camera                  axisangle class>class euler focal focalpixel fovy ipd mode name=camera
                             output pos principal principalpixel projection quat resolution
                             sensorsize target>body user xyaxes zaxis
body/light                   active ambient attenuation bulbradius castshadow class>class cutoff
                             diffuse dir directional exponent intensity mode name=light pos range
                             softness specular target>body texture>texture type
body/plugin                  instance>plugin plugin
body/plugin/config           key value
body/flexcomp                axisangle cellcount count dim dof element euler file flatskin group
                             inertiabox mass material>material mesh>mesh name=flex origin point pos
                             quat radius rgba rigid scale spacing texcoord type xyaxes zaxis
body/flexcomp/edge           damping equality solimp solref stiffness
body/flexcomp/elasticity     damping elastic2d poisson section sectionsize shear thickness yield
                             young
body/flexcomp/contact        activelayers conaffinity condim contype friction gap margin passive
                             priority selfcollide solimp solmix solref
body/flexcomp/pin            grid gridrange id range
body/flexcomp/plugin         instance>plugin plugin
body/flexcomp/plugin/config  key value
deformable                   -
deformable/flex              body>body* cellcount dim dof element elemtexcoord flatskin group
                             material>material name=flex node>body* nodecoord radius rgba texcoord
                             vertex
deformable/flex/contact      activelayers conaffinity condim contype friction gap margin passive
                             priority selfcollide solimp solmix solref
deformable/flex/edge         damping stiffness
deformable/flex/elasticity   damping elastic2d poisson section sectionsize shear thickness yield
                             young
deformable/skin              face file group inflate material>material name=skin rgba texcoord
                             vertex
deformable/skin/bone         bindpos bindquat body>body vertid vertweight
contact                      -
contact/pair                 adhesion class>class condim friction gap geom1>geom geom2>geom margin
                             name=pair solimp solref solreffriction
contact/exclude              body1>body body2>body name=exclude
tendon                       -
tendon/spatial               actuatorfrclimited actuatorfrcrange armature class>class damping
                             frictionloss group limited margin material>material name=tendon range
                             rgba solimpfriction solimplimit solreffriction solreflimit
                             springlength springyield stiffness user width
tendon/spatial/site          site>site
tendon/spatial/geom          geom>geom sidesite>site
tendon/spatial/pulley        divisor
tendon/fixed                 actuatorfrclimited actuatorfrcrange armature class>class damping
                             frictionloss group limited margin name=tendon range solimpfriction
                             solimplimit solreffriction solreflimit springlength springyield
                             stiffness user
tendon/fixed/joint           coef joint>joint
equality                     -
equality/connect             active anchor body1>body body2>body class>class name=equality
                             site1>site site2>site solimp solref
equality/weld                active anchor body1>body body2>body class>class name=equality relpose
                             site1>site site2>site solimp solref torquescale
equality/joint               active class>class joint1>joint joint2>joint name=equality polycoef
                             solimp solref
equality/tendon              active class>class name=equality polycoef solimp solref tendon1>tendon
                             tendon2>tendon
equality/flex                active class>class flex>flex name=equality solimp solref
equality/flexstrain          active cell class>class flex>flex name=equality solimp solref
actuator                     -
actuator/general             actdim actearly actlimited actrange armature biasprm biastype
                             body>body class>class cranklength cranksite>site ctrllimited ctrlrange
                             damping delay dynprm dyntype ffrange forcelimited forcerange gainprm
                             gaintype gear group inheritrange input interp joint>joint
                             jointinparent>joint lengthrange name=actuator nsample refsite>site
                             site>site slidersite>site tendon>tendon user velrange
actuator/motor               armature class>class cranklength cranksite>site ctrllimited ctrlrange
                             damping delay forcelimited forcerange gear group interp joint>joint
                             jointinparent>joint lengthrange name=actuator nsample refsite>site
                             site>site slidersite>site tendon>tendon user
actuator/position            armature class>class cranklength cranksite>site ctrllimited ctrlrange
                             damping dampratio delay forcelimited forcerange gear group
                             inheritrange interp joint>joint jointinparent>joint kp kv lengthrange
                             name=actuator nsample refsite>site site>site slidersite>site
                             tendon>tendon timeconst user
actuator/velocity            armature class>class cranklength cranksite>site ctrllimited ctrlrange
                             damping delay forcelimited forcerange gear group interp joint>joint
                             jointinparent>joint kv lengthrange name=actuator nsample refsite>site
                             site>site slidersite>site tendon>tendon user
actuator/intvelocity         actlimited actrange armature class>class cranklength cranksite>site
                             ctrllimited ctrlrange damping dampratio delay forcelimited forcerange
                             gear group inheritrange interp joint>joint jointinparent>joint kp kv
                             lengthrange name=actuator nsample refsite>site site>site
                             slidersite>site tendon>tendon user
actuator/orientation         class>class ctrlrange dampratio delay forcelimited forcerange group
                             input interp joint>joint kp kv name=actuator nsample refsite>site
                             site>site user
actuator/pid                 armature class>class cranklength cranksite>site ctrllimited ctrlrange
                             damping dampratio delay ffrange forcelimited forcerange gear group
                             imax inheritrange input interp joint>joint jointinparent>joint ki kp
                             kv lengthrange name=actuator nsample posrange refsite>site site>site
                             slewmax slidersite>site tendon>tendon user velrange
actuator/damper              armature class>class cranklength cranksite>site ctrlrange damping
                             delay forcelimited forcerange gear group interp joint>joint
                             jointinparent>joint kv lengthrange name=actuator nsample refsite>site
                             site>site slidersite>site tendon>tendon user
actuator/cylinder            area armature bias class>class cranklength cranksite>site ctrllimited
                             ctrlrange damping delay diameter forcelimited forcerange gear group
                             interp joint>joint jointinparent>joint lengthrange name=actuator
                             nsample refsite>site site>site slidersite>site tendon>tendon timeconst
                             user
actuator/muscle              armature class>class cranklength cranksite>site ctrllimited ctrlrange
                             damping delay force forcelimited forcerange fpmax fvmax gear group
                             interp joint>joint jointinparent>joint lengthrange lmax lmin
                             name=actuator nsample range scale slidersite>site tausmooth
                             tendon>tendon timeconst user vmax
actuator/adhesion            body>body class>class ctrlrange delay forcelimited forcerange gain
                             group interp name=actuator nsample user
actuator/dcmotor             armature class>class cogging controller cranklength cranksite>site
                             ctrllimited ctrlrange damping delay gear group inductance input interp
                             joint>joint jointinparent>joint lengthrange lugre motorconst
                             name=actuator nominal nsample refsite>site resistance saturation
                             site>site slidersite>site tendon>tendon thermal user
actuator/plugin              actdim actearly actlimited actrange armature class>class cranklength
                             cranksite>site ctrllimited ctrlrange damping delay dynprm dyntype
                             forcelimited forcerange gear group instance>plugin interp joint>joint
                             jointinparent>joint lengthrange name=actuator nsample plugin site>site
                             slidersite>site tendon>tendon user
actuator/plugin/config       key value
sensor                       -
sensor/touch                 cutoff delay interp interval name=sensor noise nsample site>site user
sensor/accelerometer         cutoff delay interp interval name=sensor noise nsample site>site user
sensor/velocimeter           cutoff delay interp interval name=sensor noise nsample site>site user
sensor/gyro                  cutoff delay interp interval name=sensor noise nsample site>site user
sensor/force                 cutoff delay interp interval name=sensor noise nsample site>site user
sensor/torque                cutoff delay interp interval name=sensor noise nsample site>site user
sensor/magnetometer          cutoff delay interp interval name=sensor noise nsample site>site user
sensor/camprojection         camera>camera cutoff delay interp interval name=sensor noise nsample
                             site>site user
sensor/rangefinder           camera>camera cutoff data delay interp interval name=sensor noise
                             nsample site>site user
sensor/jointpos              cutoff delay interp interval joint>joint name=sensor noise nsample
                             user
sensor/jointvel              cutoff delay interp interval joint>joint name=sensor noise nsample
                             user
sensor/tendonpos             cutoff delay interp interval name=sensor noise nsample tendon>tendon
                             user
sensor/tendonvel             cutoff delay interp interval name=sensor noise nsample tendon>tendon
                             user
sensor/actuatorpos           actuator>actuator cutoff delay interp interval name=sensor noise
                             nsample user
sensor/actuatorvel           actuator>actuator cutoff delay interp interval name=sensor noise
                             nsample user
sensor/actuatorfrc           actuator>actuator cutoff delay interp interval name=sensor noise
                             nsample user
sensor/jointactuatorfrc      cutoff delay interp interval joint>joint name=sensor noise nsample
                             user
sensor/tendonactuatorfrc     cutoff delay interp interval name=sensor noise nsample tendon>tendon
                             user
sensor/ballquat              cutoff delay interp interval joint>joint name=sensor noise nsample
                             user
sensor/ballangvel            cutoff delay interp interval joint>joint name=sensor noise nsample
                             user
sensor/jointlimitpos         cutoff delay interp interval joint>joint name=sensor noise nsample
                             user
sensor/jointlimitvel         cutoff delay interp interval joint>joint name=sensor noise nsample
                             user
sensor/jointlimitfrc         cutoff delay interp interval joint>joint name=sensor noise nsample
                             user
sensor/tendonlimitpos        cutoff delay interp interval name=sensor noise nsample tendon>tendon
                             user
sensor/tendonlimitvel        cutoff delay interp interval name=sensor noise nsample tendon>tendon
                             user
sensor/tendonlimitfrc        cutoff delay interp interval name=sensor noise nsample tendon>tendon
                             user
sensor/framepos              cutoff delay interp interval name=sensor noise nsample
                             objname>@objtype objtype refname>@reftype reftype user
sensor/framequat             cutoff delay interp interval name=sensor noise nsample
                             objname>@objtype objtype refname>@reftype reftype user
sensor/framexaxis            cutoff delay interp interval name=sensor noise nsample
                             objname>@objtype objtype refname>@reftype reftype user
sensor/frameyaxis            cutoff delay interp interval name=sensor noise nsample
                             objname>@objtype objtype refname>@reftype reftype user
sensor/framezaxis            cutoff delay interp interval name=sensor noise nsample
                             objname>@objtype objtype refname>@reftype reftype user
sensor/framelinvel           cutoff delay interp interval name=sensor noise nsample
                             objname>@objtype objtype refname>@reftype reftype user
sensor/frameangvel           cutoff delay interp interval name=sensor noise nsample
                             objname>@objtype objtype refname>@reftype reftype user
sensor/framelinacc           cutoff delay interp interval name=sensor noise nsample
                             objname>@objtype objtype user
sensor/frameangacc           cutoff delay interp interval name=sensor noise nsample
                             objname>@objtype objtype user
sensor/subtreecom            body>body cutoff delay interp interval name=sensor noise nsample user
sensor/subtreelinvel         body>body cutoff delay interp interval name=sensor noise nsample user
sensor/subtreeangmom         body>body cutoff delay interp interval name=sensor noise nsample user
sensor/insidesite            cutoff delay enclosed interp interval name=sensor noise nsample
                             objname>@objtype objtype site>site user
sensor/distance              body1>body body2>body cutoff delay geom1>geom geom2>geom interp
                             interval name=sensor noise nsample user
sensor/normal                body1>body body2>body cutoff delay geom1>geom geom2>geom interp
                             interval name=sensor noise nsample user
sensor/fromto                body1>body body2>body cutoff delay geom1>geom geom2>geom interp
                             interval name=sensor noise nsample user
sensor/contact               body1>body body2>body cutoff data delay geom1>geom geom2>geom interp
                             interval name=sensor noise nsample num reduce site>site subtree1>body
                             subtree2>body user
sensor/e_potential           cutoff delay interp interval name=sensor noise nsample user
sensor/e_kinetic             cutoff delay interp interval name=sensor noise nsample user
sensor/clock                 cutoff delay interp interval name=sensor noise nsample user
sensor/tactile               cutoff delay geom>geom interp interval mesh>mesh name=sensor nsample
                             user
sensor/user                  cutoff datatype dim name=sensor needstage noise objname>@objtype
                             objtype user
sensor/plugin                cutoff instance>plugin name=sensor objname>@objtype objtype plugin
                             refname>@reftype reftype user
sensor/plugin/config         key value
custom                       -
custom/numeric               data name=numeric size
custom/text                  data name=text
custom/tuple                 name=tuple
custom/tuple/element         objname>@objtype objtype prm
keyframe                     -
keyframe/key                 act ctrl mpos mquat name=key plastic qpos qvel time
include                      file
body/frame                   axisangle childclass>class euler name=frame pos quat xyaxes zaxis
body/replicate               count euler offset sep
worldbody                    -
"""

#: Schema keys whose children are read in the context of another key.
_CHILD_CONTEXT = {"worldbody": "body", "body/frame": "body", "body/replicate": "body"}
#: Elements that may contain themselves.
_RECURSIVE = frozenset({"body", "default"})


def _parse(table: str) -> dict[str, ElementSpec]:
    entries: list[tuple[str, list[str]]] = []
    for line in table.splitlines():
        if not line.strip():
            continue
        if line[0].isspace():
            entries[-1][1].extend(line.split())
        else:
            key, *words = line.split()
            entries.append((key, words))
    specs: dict[str, ElementSpec] = {}
    for key, words in entries:
        attributes: set[str] = set()
        declares: dict[str, str] = {}
        references: dict[str, str] = {}
        lists: set[str] = set()
        for word in words:
            if word == "-":
                continue
            if "=" in word:
                attribute, namespace = word.split("=")
                declares[attribute] = namespace
            elif ">" in word:
                attribute, namespace = word.split(">")
                if namespace.endswith("*"):
                    namespace = namespace[:-1]
                    lists.add(attribute)
                references[attribute] = namespace
            else:
                attribute = word
            attributes.add(attribute)
        specs[key] = ElementSpec(
            key=key,
            attributes=frozenset(attributes),
            declares=MappingProxyType(declares),
            references=MappingProxyType(references),
            list_references=frozenset(lists),
        )
    return specs


#: The MuJoCo release whose printed schema the table mirrors, attribute for attribute.
SCHEMA_RELEASE = "4.0.0"

#: Every element MuJoCo knows, by schema key.
SCHEMA: Mapping[str, ElementSpec] = MappingProxyType(_parse(_TABLE))

#: Every namespace a name can live in.
NAMESPACES: frozenset[str] = frozenset(
    ns
    for spec in SCHEMA.values()
    for ns in (*spec.declares.values(), *spec.references.values())
    if not ns.startswith("@")
)

#: The namespace that an ``objtype``/``reftype`` keyword points into.
OBJTYPE_NAMESPACES: Mapping[str, str] = MappingProxyType(
    {
        "body": "body",
        "xbody": "body",
        "joint": "joint",
        "geom": "geom",
        "site": "site",
        "camera": "camera",
        "light": "light",
        "flex": "flex",
        "mesh": "mesh",
        "skin": "skin",
        "hfield": "hfield",
        "texture": "texture",
        "material": "material",
        "pair": "pair",
        "exclude": "exclude",
        "equality": "equality",
        "tendon": "tendon",
        "actuator": "actuator",
        "sensor": "sensor",
        "numeric": "numeric",
        "text": "text",
        "tuple": "tuple",
        "key": "key",
        "plugin": "plugin",
        "frame": "frame",
    }
)


def child_key(context: str | None, tag: str) -> str | None:
    """The schema key of a ``tag`` element inside an element whose key is ``context``.

    ``context`` is ``None`` at the document root. Returns ``None`` for an element
    the table does not know; its children are then read in the parent's context.

    Examples:
        >>> child_key(None, "mujoco"), child_key("body", "body"), child_key("body", "wheel")
        ('mujoco', 'body', None)

    """
    if tag == "include":
        return "include"
    if context is None:
        return "mujoco" if tag == "mujoco" else None
    if context == "mujoco":
        return tag if tag in SCHEMA else None
    base = _CHILD_CONTEXT.get(context, context)
    if tag == base and base in _RECURSIVE:  # a body in a body, a class in a class
        return base
    key = f"{base}/{tag}"
    return key if key in SCHEMA else None


def reference_namespace(
    spec: ElementSpec, attribute: str, values: Mapping[str, object]
) -> str | None:
    """The namespace ``attribute`` of an element refers to, given its other attribute values.

    Resolves ``@objtype``-style entries through the value of the named attribute.

    Examples:
        >>> reference_namespace(SCHEMA["sensor/framepos"], "objname", {"objtype": "xbody"})
        'body'

    """
    namespace = spec.references.get(attribute)
    if namespace is None or not namespace.startswith("@"):
        return namespace
    selector = values.get(namespace[1:])
    return OBJTYPE_NAMESPACES.get(selector) if isinstance(selector, str) else None


#: Contexts tried, in order, for an element read without its parents.
_CONTEXTS = (
    None,
    "mujoco",
    "body",
    "asset",
    "actuator",
    "sensor",
    "tendon",
    "equality",
    "contact",
    "keyframe",
    "custom",
    "deformable",
    "extension",
    "default",
)


def children_context(key: str | None, parent_context: str | None) -> str | None:
    """The context an element's children are read in.

    An element the table does not know (``key`` is ``None``), and an include, pass
    their parent's context on, so future wrapper elements keep their contents typed.

    Examples:
        >>> children_context("body/frame", "body"), children_context(None, "body")
        ('body/frame', 'body')

    """
    if key is None or key == "include":
        return parent_context
    return key


def guess_context(tag: str) -> str | None:
    """The most likely parent context of a ``tag`` element read on its own.

    Examples:
        >>> guess_context("mujoco"), guess_context("geom"), guess_context("motor")
        (None, 'body', 'actuator')

    """
    for context in _CONTEXTS:
        if child_key(context, tag) is not None:
            return context
    return None
