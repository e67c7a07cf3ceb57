"""The schema cases of actuators and sensors: one model per reference of each.

References that exclude each other (an actuator's ``joint``, ``tendon``, ``site`` and
``body``; a distance sensor's geoms and bodies) get a model each.
"""

from __future__ import annotations

from tests.support.schema_model import model

# -- actuators ------------------------------------------------------------------------------

#: What each actuator needs besides its transmission to compile.
ACTUATOR_SETTINGS = {
    "general": "",
    "motor": "",
    "position": 'kp="1"',
    "velocity": 'kv="1"',
    "intvelocity": 'kp="1" actrange="-1 1"',
    "pid": 'kp="1"',
    "damper": 'kv="1" ctrlrange="0 1"',
    "cylinder": "",
    "muscle": 'lengthrange="0.1 1"',
    "dcmotor": 'motorconst="1" resistance="1"',
    "orientation": 'kp="1"',
    "plugin": 'plugin="mujoco.pid"',
    "adhesion": 'ctrlrange="0 1"',
}
#: The transmission each reference attribute makes, as attributes (an orientation
#: actuator drives a ball joint).
_TRANSMISSIONS = {
    "joint": 'joint="hinge"',
    "jointinparent": 'jointinparent="hinge"',
    "tendon": 'tendon="cord"',
    "site": 'site="shoulder"',
    "refsite": 'site="shoulder" refsite="elbow"',
    "cranksite": 'cranksite="shoulder" slidersite="wrist" cranklength="0.3"',
    "slidersite": 'cranksite="shoulder" slidersite="wrist" cranklength="0.3"',
    "body": 'body="forearm"',
    "class": 'class="cls" joint="hinge"',
    "instance": 'instance="gains" joint="hinge"',
}
_PID_INSTANCE = (
    '<plugin plugin="mujoco.pid"><instance name="gains">'
    '<config key="kp" value="1"/></instance></plugin>'
)


def actuator_case(tag: str, attribute: str) -> str:
    """The model of an ``actuator/<tag>`` using its reference ``attribute``."""
    transmission = _TRANSMISSIONS[attribute]
    if tag == "orientation":
        transmission = transmission.replace('"hinge"', '"swivel"')
        if attribute == "site":
            transmission = _TRANSMISSIONS["refsite"]
    if tag == "adhesion":
        transmission = transmission.replace('joint="hinge"', 'body="forearm"')
    settings = ACTUATOR_SETTINGS[tag]
    if tag == "plugin" and attribute == "instance":
        return model(extension=_PID_INSTANCE, actuator=f"<plugin {transmission}/>")
    if tag == "plugin":
        line = f'<plugin {settings} {transmission}><config key="kp" value="1"/></plugin>'
        return model(extension='<plugin plugin="mujoco.pid"/>', actuator=line)
    return model(actuator=f"<{tag} {settings} {transmission}/>")


# -- sensors --------------------------------------------------------------------------------

#: The attributes of a sensor using each single reference.
_SENSOR_REFERENCES = {
    "site": 'site="shoulder"',
    "joint": 'joint="hinge"',
    "tendon": 'tendon="cord"',
    "actuator": 'actuator="act"',
    "body": 'body="forearm"',
    "camera": 'camera="eye"',
}
#: The sensors that need a site and a camera.
_CAMERA_SENSORS = frozenset({"camprojection"})
#: The sensors whose joint is a ball joint.
_BALL_SENSORS = frozenset({"ballquat", "ballangvel"})
#: A frame sensor's object and reference object, by reference attribute: each frame
#: sensor reads a different object type, so the type mapping is used widely.
_FRAME_OBJECTS = {
    "framepos": ("site", "shoulder"),
    "framequat": ("body", "forearm"),
    "framexaxis": ("xbody", "arm"),
    "frameyaxis": ("geom", "lower"),
    "framezaxis": ("camera", "eye"),
    "framelinvel": ("site", "wrist"),
    "frameangvel": ("geom", "knob"),
    "framelinacc": ("body", "socket"),
    "frameangacc": ("site", "elbow"),
}
#: The pairs of a collision sensor (distance, normal, fromto, contact), by attribute.
_PAIRS = {
    "geom1": 'geom1="upper" geom2="knob"',
    "geom2": 'geom1="upper" geom2="knob"',
    "body1": 'body1="arm" body2="socket"',
    "body2": 'body1="arm" body2="socket"',
    "subtree1": 'subtree1="arm" subtree2="socket"',
    "subtree2": 'subtree1="arm" subtree2="socket"',
    "site": 'site="shoulder"',
}
_ACTUATED = '<motor name="act" joint="hinge"/>'
_TOUCH_CONFIG = (
    '<config key="size" value="2 2"/><config key="fov" value="45 45"/>'
    '<config key="gamma" value="0"/><config key="nchannel" value="1"/>'
)


def sensor_case(tag: str, attribute: str) -> str:
    """The model of a ``sensor/<tag>`` using its reference ``attribute``."""
    if tag.startswith("frame"):
        objtype, objname = _FRAME_OBJECTS[tag]
        line = f'<{tag} objtype="{objtype}" objname="{objname}"'
        if attribute == "refname":
            line += ' reftype="body" refname="socket"'
        return model(sensor=line + "/>")
    if tag in ("distance", "normal", "fromto", "contact"):
        return model(sensor=f"<{tag} {_PAIRS[attribute]}/>")
    if tag == "plugin":
        return _plugin_sensor(attribute)
    special = {
        "insidesite": '<insidesite site="shoulder" objtype="body" objname="forearm"/>',
        "tactile": '<tactile geom="upper" mesh="tet"/>',
        "user": '<user objtype="site" objname="shoulder" dim="1" needstage="pos" datatype="real"/>',
    }
    if tag in special:
        return model(sensor=special[tag])
    reference = _SENSOR_REFERENCES[attribute]
    if tag in _CAMERA_SENSORS:
        reference = 'site="shoulder" camera="eye"'
    if tag in _BALL_SENSORS:
        reference = 'joint="swivel"'
    actuator = {"actuator": _ACTUATED} if attribute == "actuator" else {}
    return model(**actuator, sensor=f"<{tag} {reference}/>")


def _plugin_sensor(attribute: str) -> str:
    on = 'objtype="site" objname="shoulder"'
    if attribute == "instance":
        extension = (
            f'<plugin plugin="mujoco.sensor.touch_grid"><instance name="touch">{_TOUCH_CONFIG}'
            "</instance></plugin>"
        )
        return model(extension=extension, sensor=f'<plugin instance="touch" {on}/>')
    if attribute == "refname":
        on += ' reftype="site" refname="elbow"'
    line = f'<plugin plugin="mujoco.sensor.touch_grid" {on}>{_TOUCH_CONFIG}</plugin>'
    return model(extension='<plugin plugin="mujoco.sensor.touch_grid"/>', sensor=line)
