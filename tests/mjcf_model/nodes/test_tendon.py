"""Tests of ``mjcf_model.nodes.tendon``: spatial and fixed tendons and their path elements."""

from __future__ import annotations

import mujoco

from mjcf_model import Fixed, Pulley, Spatial, TendonGeom, TendonJoint, TendonSite
from mjcf_model.serializers import load
from tests.conftest import FIXTURES
from tests.support.node_classes import declared_in, loaded_from, text_round_trip_differences

MECHANICS = FIXTURES / "mechanics.xml"
MODULE = "mjcf_model.nodes.tendon"

#: MuJoCo's wrap types of each path element (a geom wraps as a sphere or a cylinder).
WRAPS = {
    TendonJoint: {mujoco.mjtWrap.mjWRAP_JOINT},
    Pulley: {mujoco.mjtWrap.mjWRAP_PULLEY},
    TendonSite: {mujoco.mjtWrap.mjWRAP_SITE},
    TendonGeom: {mujoco.mjtWrap.mjWRAP_SPHERE, mujoco.mjtWrap.mjWRAP_CYLINDER},
}


def _wraps(compiled: mujoco.MjModel, name: str) -> range:
    index = compiled.tendon(name).id
    return range(
        compiled.tendon_adr[index], compiled.tendon_adr[index] + compiled.tendon_num[index]
    )


def test_each_path_is_the_one_mujoco_wraps_in_document_order() -> None:
    """Path elements are MuJoCo's wraps, in order; a fixed tendon's ``joints`` hold its coefs."""
    model = load(MECHANICS)
    found = loaded_from(model, MODULE)
    assert {
        "Tendon",
        "Spatial",
        "Fixed",
        "TendonSite",
        "TendonGeom",
        "TendonJoint",
        "Pulley",
    } == found
    assert found <= declared_in(MODULE)
    compiled = mujoco.MjModel.from_xml_path(str(MECHANICS))
    for tendon in model.tendon.elements:
        assert isinstance(tendon, (Spatial, Fixed))
        wraps = _wraps(compiled, tendon.name)
        kinds = compiled.wrap_type[wraps].tolist()
        assert len(kinds) == len(tendon.elements)
        assert all(kind in WRAPS[type(e)] for e, kind in zip(tendon.elements, kinds, strict=True))
        if isinstance(tendon, Fixed):
            assert [j.coef for j in tendon.joints] == compiled.wrap_prm[wraps].tolist()
            assert [compiled.joint(j.joint).id for j in tendon.joints] == compiled.wrap_objid[
                wraps
            ].tolist()
    rope = next(t for t in model.tendon.elements if t.name == "rope")
    pulley = next(e for e in rope.elements if isinstance(e, Pulley))
    assert pulley.divisor == 2 == compiled.wrap_prm[_wraps(compiled, "rope")][2]
    assert rope.width == compiled.tendon_width[compiled.tendon("rope").id]
    assert text_round_trip_differences(MECHANICS.read_text()) == []
