"""The shipped ``models()`` strategy: every draw compiles, and it reaches the whole schema."""

from __future__ import annotations

import xml.etree.ElementTree as ET

import mujoco
import pytest
from hypothesis import HealthCheck, Phase, find, settings
from hypothesis.errors import NoSuchExample

from mjcf_model import Mujoco
from mjcf_model.serializers import dumps
from mjcf_model.strategies import models

#: What a drawn model may hold, each found by an XPath over its text.
FAMILIES = {
    "inline mesh": ".//asset/mesh[@vertex]",
    "mesh with faces": ".//asset/mesh[@face]",
    "mesh geom": ".//geom[@type='mesh']",
    "spatial tendon": ".//tendon/spatial",
    "wrapping geom with side site": ".//tendon/spatial/geom[@sidesite]",
    "fixed tendon": ".//tendon/fixed",
    "joint transmission": ".//actuator/*[@joint]",
    "tendon transmission": ".//actuator/*[@tendon]",
    "site transmission": ".//actuator/*[@site]",
    "site transmission with refsite": ".//actuator/*[@refsite]",
    "body transmission": ".//actuator/adhesion[@body]",
    "jointinparent transmission": ".//actuator/*[@jointinparent]",
    "activation": ".//actuator/general[@dyntype='filter']",
    "connect bodies": ".//equality/connect[@body1]",
    "connect sites": ".//equality/connect[@site1]",
    "weld with relpose": ".//equality/weld[@relpose]",
    "weld sites": ".//equality/weld[@site1]",
    "joint coupling": ".//equality/joint[@polycoef]",
    "tendon coupling": ".//equality/tendon",
    "camera targetbody": ".//camera[@mode='targetbody'][@target]",
    "light targetbodycom": ".//light[@mode='targetbodycom'][@target]",
    "nested frame": ".//frame/frame",
    "frame holding a body": ".//frame/body",
    "euler frame": ".//frame[@euler]",
    "replicate": ".//replicate[@count][@offset]",
    "replicate with separator": ".//replicate[@sep]",
    "nested default class": ".//default/default/default",
    "childclass": ".//body[@childclass]",
    "radian angles": ".//compiler[@angle='radian']",
    "free joint": ".//freejoint",
    "mocap body": ".//body[@mocap='true']",
    "key qpos": ".//key[@qpos]",
    "key qvel": ".//key[@qvel]",
    "key ctrl": ".//key[@ctrl]",
    "key act": ".//key[@act]",
    "key mocap pose": ".//key[@mpos][@mquat]",
    "explicit inertia": ".//inertial[@mass]",
}

#: One derandomized search through draws until every family has occurred (the draws
#: differ between the checkout and the installed wheel, so no fixed count is assumed).
SEARCH = settings(
    max_examples=3000,
    derandomize=True,
    database=None,
    deadline=None,
    phases=[Phase.generate],
    suppress_health_check=list(HealthCheck),
)


def test_every_family_is_drawn_and_compiles() -> None:
    """Draws reach every family, sizes of a millimetre and positions of metres; all compile."""
    seen: set[str] = set()
    scales: list[float] = []

    def reaches_everything(model: Mujoco) -> bool:
        text = dumps(model)
        compiled = mujoco.MjModel.from_xml_string(text)
        root = ET.fromstring(text)
        seen.update(name for name, path in FAMILIES.items() if root.find(path) is not None)
        if compiled.ngeom:
            scales.extend(float(v) for v in compiled.geom_size[:, 0] if v > 0)
            scales.extend(float(abs(v)) for v in compiled.body_pos.ravel())
        return seen >= set(FAMILIES) and min(scales) < 0.005 and max(scales) > 2.0

    try:
        find(models(), reaches_everything, settings=SEARCH)
    except NoSuchExample:
        pytest.fail(f"never drawn in 3000 models: {sorted(set(FAMILIES) - seen)}")
