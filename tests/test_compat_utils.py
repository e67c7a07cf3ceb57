"""compat ``mjcf_utils``: the same names and signatures as robosuite's, and the golden checks.

The golden checks are items 1 to 6 of section 6 of the robosuite contract
(``/work/shared/reference/robosuite_contract.md``), each run against robosuite
1.5.2 itself and against the exact text the contract recorded.
"""

from __future__ import annotations

import inspect
import os
import uuid
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from PIL import Image
from robosuite.models import assets_root as RS_ASSETS

from mjcf_model import MjcfLookupError
from mjcf_model.compat import mjcf_utils as compat_module
from tests.support.compat_utils import (
    CASES,
    E2,
    RS_CONSTANTS,
    comparable,
    differential,
    ours,
    rs,
    run,
    same_arrays,
)

#: robosuite's public functions and classes (defined in its module) and constants.
RS_FUNCTIONS = sorted(
    name
    for name, value in vars(rs).items()
    if callable(value) and getattr(value, "__module__", None) == rs.__name__
)


def test_every_public_name_of_robosuite_is_here() -> None:
    """Every function, class and constant of robosuite's module exists here, public in __all__."""
    assert len(RS_FUNCTIONS) == 33 and len(RS_CONSTANTS) == 15
    for name in RS_FUNCTIONS + RS_CONSTANTS:
        assert hasattr(compat_module, name), name
        assert (name in compat_module.__all__) == (not name.startswith("_")), name
    assert compat_module.__all__ == sorted(compat_module.__all__)
    assert set(compat_module.__all__) <= set(RS_FUNCTIONS + RS_CONSTANTS)


@pytest.mark.parametrize("name", RS_FUNCTIONS)
def test_signatures_match_robosuite(name: str) -> None:
    """Each function takes the same parameters as robosuite's: names, kinds and defaults."""

    def parameters(function: Any) -> list[tuple[str, Any, Any]]:
        signature = inspect.signature(function)
        return [(p.name, p.kind, p.default) for p in signature.parameters.values()]

    assert parameters(getattr(ours, name)) == parameters(getattr(rs, name))


@pytest.mark.parametrize("name", RS_CONSTANTS)
def test_constants_match_robosuite(name: str) -> None:
    """Each constant has robosuite's value and type; ordered ones have robosuite's order."""
    mine, theirs = getattr(ours, name), getattr(rs, name)
    assert type(mine) is type(theirs)
    assert mine == theirs
    if not isinstance(mine, set):  # a set's iteration order depends on how it was built
        assert comparable(mine, {}) == comparable(theirs, {}) and list(mine) == list(theirs)


# -- golden check 1: number text ----------------------------------------------------------


@pytest.mark.parametrize(
    ("value", "text"),
    [
        ([0.5, 0, 1], "0.5 0 1"),
        (np.array([0.5, 0, 1]), "0.5 0.0 1.0"),
        (np.array([1, 2, 3]), "1 2 3"),
        (np.float32([0.1, 0.2]), "0.10000000149011612 0.20000000298023224"),
        ([1e-8, 1e20], "1e-08 1e+20"),
        ([0.1 + 0.2], "0.30000000000000004"),
        ([], ""),
    ],
)
def test_golden_array_to_string(value: Any, text: str) -> None:
    """array_to_string gives robosuite's text (golden check 1)."""
    assert ours.array_to_string(value) == rs.array_to_string(value) == text


@pytest.mark.parametrize("text", [" 0 1 2 ", "1 None 2", "0  1", ""])
def test_golden_string_to_array(text: str) -> None:
    """string_to_array gives robosuite's array, or its ValueError (golden check 1)."""
    mine, my_error = run(ours.string_to_array, text)
    theirs, their_error = run(rs.string_to_array, text)
    assert my_error == their_error and same_arrays(mine, theirs)
    assert (my_error is ValueError) == (text in ("0  1", ""))


# -- golden check 2: constructors -----------------------------------------------------------

BUILT = [
    ("new_site", ("s",), {}, '<site pos="0 0 0" size="0.005" rgba="1 0 0 1" name="s" />'),
    ("new_site", (None,), {}, '<site pos="0 0 0" size="0.005" rgba="1 0 0 1" />'),
    (
        "new_geom",
        ("g", "box", [0.1, 0.1, 0.1]),
        {},
        '<geom type="box" size="0.1 0.1 0.1" pos="0 0 0" group="0" name="g" />',
    ),
    (
        "new_geom",
        ("g", "sphere", [0.1]),
        {"group": None, "rgba": None, "material": "m"},
        '<geom material="m" type="sphere" size="0.1" pos="0 0 0" name="g" />',
    ),
    ("new_body", ("b",), {}, '<body pos="0 0 0" name="b" />'),
    (
        "new_joint",
        ("j",),
        {"type": "free", "damping": "0.0005"},
        '<joint type="free" damping="0.0005" name="j" />',
    ),
    (
        "new_actuator",
        (),
        {"joint": "gz", "act_type": "position", "name": "a", "kp": "500"},
        '<position kp="500" name="a" joint="gz" />',
    ),
    (
        "new_inertial",
        (),
        {"mass": 1.0, "diaginertia": [1, 1, 1]},
        '<inertial diaginertia="1 1 1" mass="1.0" pos="0 0 0" />',
    ),
    (
        "new_element",
        ("body", None),
        {"pos": [0, 0, 1], "quat": None, "mass": 0.5, "flag": True},
        '<body pos="0 0 1" mass="0.5" flag="true" />',
    ),
]


@pytest.mark.parametrize(("function", "args", "kwargs", "xml"), BUILT)
def test_golden_constructors(function: str, args: Any, kwargs: Any, xml: str) -> None:
    """The new_* constructors give robosuite's bytes (golden check 2)."""
    mine = getattr(ours, function)(*args, **kwargs)
    theirs = getattr(rs, function)(*args, **kwargs)
    CASES[function] += 1
    assert ET.tostring(mine, encoding="unicode") == ET.tostring(theirs, encoding="unicode") == xml


# -- golden check 3: add_prefix -------------------------------------------------------------
E2_PREFIXED = (
    '<body name="p_b" childclass="p_c"><geom name="p_g" material="p_m" mesh="p_mesh" '
    'class="p_k" /><joint name="p_j" /><site name="p_s" type="sphere" />'
    '<weld body1="p_b" body2="p_x" /><camera name="p_cam" mode="fixed" /><light name="p_l" />'
    '<foo name="p_f" rgba="1 0 0 1" texture="p_t" /><exclude body1="p_a" body2="p_b" />'
    '<pair geom1="p_g" geom2="p_h" /><motor joint="p_j" name="p_mot" />'
    '<fixed name="p_fx"><joint joint="p_j" coef="1" /></fixed></body>'
)


@pytest.mark.parametrize(
    "options",
    [
        {},
        {"tags": "geom"},
        {"tags": ["geom", "joint"], "attribs": "name"},
        {"exclude": lambda x: not isinstance(x, str) and x.tag == "body"},
        {"exclude": lambda x: x in ("g", "m")},
    ],
    ids=["default", "tags", "tags-attribs", "exclude-element", "exclude-string"],
)
def test_golden_add_prefix(options: dict[str, Any]) -> None:
    """add_prefix on the contract's e2 tree, applied twice, gives robosuite's bytes (check 3)."""

    def twice(module: Any, root: ET.Element) -> None:
        module.add_prefix(root, "p_", **options)
        module.add_prefix(root, "p_", **options)

    differential("add_prefix", ET.fromstring(E2), twice)
    if not options:
        root = ET.fromstring(E2)
        ours.add_prefix(root, "p_")
        assert ET.tostring(root, encoding="unicode") == E2_PREFIXED


def test_golden_add_prefix_skips_values_that_start_with_the_prefix() -> None:
    """Prefix "p" leaves "p_x" and "pp" alone; an empty name becomes the prefix (check 3)."""
    root = ET.fromstring('<body name="p_x"><geom name="pp"/><site name=""/></body>')
    ours.add_prefix(root, "p")
    assert ET.tostring(root) == b'<body name="p_x"><geom name="pp" /><site name="p" /></body>'
    differential("add_prefix", ET.fromstring('<body name="p_x"><geom name="pp"/></body>'), twice_p)


def twice_p(module: Any, root: ET.Element) -> None:
    """add_prefix with prefix "p", twice."""
    module.add_prefix(root, "p")
    module.add_prefix(root, "p")


# -- golden check 4: queries ----------------------------------------------------------------

E3 = (
    '<worldbody><body name="a"><geom name="g1" group="1"/><body name="b"><geom name="g2"/>'
    '<geom name="g3" group="0"/><geom name="g4" group="2"/><joint name="j1"/><site name="s1"/>'
    '</body></body><body name="c"><geom name="g5" type="box"/></body></worldbody>'
)


def _names(value: Any) -> Any:
    if isinstance(value, ET.Element):
        return value.get("name") or value.tag
    if isinstance(value, dict):
        return [(k, _names(v)) for k, v in value.items()]
    if isinstance(value, (list, tuple)):
        return [_names(v) for v in value]
    return value


QUERIES = {
    "sort_elements": lambda m, r: m.sort_elements(r),
    "find_elements": lambda m, r: m.find_elements(r, "geom"),
    "find_elements list": lambda m, r: m.find_elements(r, "geom", return_first=False),
    "find_elements none": lambda m, r: m.find_elements(r, "camera"),
    "find_elements list none": lambda m, r: m.find_elements(r, "camera", return_first=False),
    "find_elements group": lambda m, r: m.find_elements(r, "geom", {"group": None}, False),
    "get_elements": lambda m, r: m.get_elements(r, "geom"),
    "get_elements root": lambda m, r: m.get_elements(r, "worldbody"),
    "find_parent": lambda m, r: m.find_parent(r, r[0][1][2]),
    "find_parent root": lambda m, r: m.find_parent(r, r),
}
QUERY_RESULTS = {
    "sort_elements": [
        ("root_body", ["a", "c"]),
        ("visual_geoms", ["g1"]),
        ("bodies", ["b"]),
        ("contact_geoms", ["g2", "g3", "g5"]),
        ("joints", ["j1"]),
        ("sites", ["s1"]),
    ],
    "find_elements": "g1",
    "find_elements list": ["g1", "g2", "g3", "g4", "g5"],
    "find_elements none": None,
    "find_elements list none": None,
    "find_elements group": ["g2", "g5"],
    "get_elements": [["a", "g1"], ["b", "g2"], ["b", "g3"], ["b", "g4"], ["c", "g5"]],
    "get_elements root": [],
    "find_parent": "b",
    "find_parent root": None,
}


@pytest.mark.parametrize("query", sorted(QUERIES))
def test_golden_queries(query: str) -> None:
    """Queries on the contract's e3 tree return robosuite's live elements (golden check 4)."""
    root = ET.fromstring(E3)
    function = query.split()[0]
    differential(function, root, QUERIES[query])
    assert _names(QUERIES[query](ours, root)) == QUERY_RESULTS[query]
    found = QUERIES[query](ours, root)
    elements = found if isinstance(found, list) else [found]
    live = {id(e) for e in root.iter()}
    assert all(id(e) in live for e in elements if isinstance(e, ET.Element))


def test_golden_find_elements_by_substring_returns_the_first_match() -> None:
    """With return_first, the first element whose name matches (robosuite returns None)."""
    root = ET.fromstring(E3)
    assert rs.find_elements_by_substring(root, "geom", "g", return_first=True) is None
    assert ours.find_elements_by_substring(root, "geom", "g", return_first=True) is root[0][0]
    assert _names(ours.find_elements_by_substring(root, "geom", ["4", "5"])) == ["g4", "g5"]


def test_golden_actuators_and_sensors_are_sorted_like_robosuite() -> None:
    """Children of <actuator> and sensor tags are filed as robosuite files them (golden check 4)."""
    root = ET.fromstring(
        '<mujoco><actuator><motor name="m1"/><general name="m2"/></actuator><sensor>'
        '<touch name="t"/><jointpos name="p"/><user name="u"/><framepos name="f"/>'
        '<clock name="c"/></sensor></mujoco>'
    )
    differential("sort_elements", root, lambda m, r: m.sort_elements(r))
    assert _names(ours.sort_elements(root)) == [
        ("actuators", ["m1", "m2"]),
        ("sensors", ["t", "p", "u", "f"]),
    ]


# -- golden check 5: CustomMaterial ---------------------------------------------------------


def _material(module: Any, *args: Any, **kwargs: Any) -> tuple[Any, Any]:
    material, error = run(module.CustomMaterial, *args, **kwargs)
    if error is not None:
        return error, None
    return None, (material.name, material.shared, material.tex_attrib, material.mat_attrib)


@pytest.mark.parametrize(
    ("args", "kwargs", "tex_attrib", "mat_attrib"),
    [
        (
            ("WoodDark", "dark_wood", "dark_wood_mat"),
            {
                "tex_attrib": {"type": "cube"},
                "mat_attrib": {"texrepeat": "3 3", "specular": "0.4", "shininess": "0.1"},
            },
            {"type": "cube", "name": "dark_wood", "file": "textures/dark-wood.png"},
            {
                "texrepeat": "3 3",
                "specular": "0.4",
                "shininess": "0.1",
                "name": "dark_wood_mat",
                "texture": "dark_wood",
            },
        ),
        (
            (None, "default_tex", "default_mat"),
            {
                "tex_attrib": {
                    "type": "cube",
                    "builtin": "flat",
                    "width": 100,
                    "height": 100,
                    "rgb1": np.ones(3),
                    "rgb2": np.ones(3),
                }
            },
            {
                "type": "cube",
                "builtin": "flat",
                "width": "100",
                "height": "100",
                "rgb1": "1.0 1.0 1.0",
                "rgb2": "1.0 1.0 1.0",
                "name": "default_tex",
            },
            {"name": "default_mat", "texture": "default_tex"},
        ),
        (
            ("objects/../textures/soda.png", "t", "m"),
            {"mat_attrib": {"flag": True, "n": np.float64(0.1)}},
            {"name": "t", "file": "objects/../textures/soda.png"},
            {"flag": "True", "n": "0.1", "name": "m", "texture": "t"},
        ),
        (
            ("/abs/a.png", "t", "m"),
            {"shared": True},
            {"name": "t", "file": "/abs/a.png"},
            {"name": "m", "texture": "t"},
        ),
    ],
    ids=["named", "builtin", "relative-path", "absolute-path"],
)
def test_golden_custom_material(
    args: Any, kwargs: Any, tex_attrib: dict[str, str], mat_attrib: dict[str, str]
) -> None:
    """CustomMaterial holds robosuite's dicts, in robosuite's order (golden check 5)."""
    mine, theirs = _material(ours, *args, **kwargs), _material(rs, *args, **kwargs)
    CASES["CustomMaterial"] += 1
    assert comparable(mine, {}) == comparable(theirs, {})
    if "file" in tex_attrib:
        tex_attrib = {**tex_attrib, "file": os.path.join(RS_ASSETS, tex_attrib["file"])}
    _, (_, _, my_tex, my_mat) = mine
    assert list(my_tex.items()) == list(tex_attrib.items())
    assert list(my_mat.items()) == list(mat_attrib.items())


@pytest.mark.parametrize(
    ("texture", "error"),
    [("Oak", AssertionError), ([0.1, 0.2, 0.3], AssertionError), (5, TypeError)],
)
def test_golden_custom_material_errors(texture: Any, error: type[Exception]) -> None:
    """An unknown texture name or an RGBA of three values fail as in robosuite (golden check 5)."""
    mine, theirs = _material(ours, texture, "t", "m"), _material(rs, texture, "t", "m")
    CASES["CustomMaterial"] += 1
    assert mine == theirs == (error, None)
    with pytest.raises(AssertionError, match=r"Got array of length 3\.Expected rgba"):
        ours.CustomMaterial([0.1, 0.2, 0.3], "t", "m")
    with pytest.raises(AssertionError, match="Valid options are:\ndict_keys"):
        ours.CustomMaterial("Oak", "t", "m")


def _pixels(path: str) -> Any:
    with Image.open(path) as image:
        return image.mode, image.size, np.asarray(image).copy()


def test_golden_custom_material_rgba_writes_robosuite_png() -> None:
    """An RGBA texture writes the PNG robosuite writes, at the same path (golden check 5)."""
    name = f"compat_{uuid.uuid4().hex}"
    theirs = rs.CustomMaterial([0.2, 0.4, 0.6, 1.0], name, "mat")
    their_pixels = _pixels(theirs.tex_attrib["file"])
    mine = ours.CustomMaterial([0.2, 0.4, 0.6, 1.0], name, "mat")
    my_pixels = _pixels(mine.tex_attrib["file"])
    Path(mine.tex_attrib["file"]).unlink()
    assert (
        mine.tex_attrib
        == theirs.tex_attrib
        == {"name": name, "file": f"/tmp/robosuite_temp_tex/{name}.png"}
    )
    assert mine.mat_attrib == theirs.mat_attrib == {"name": "mat", "texture": name}
    assert my_pixels[:2] == their_pixels[:2] == ("RGBA", (100, 100))
    assert np.array_equal(my_pixels[2], their_pixels[2])
    assert tuple(my_pixels[2][50, 50]) == (51, 102, 153, 255)


# -- golden check 6: add_material and recolor_collision_geoms ------------------------------

E5 = (
    '<body name="b"><geom name="v" group="1"/><geom name="c" group="0"/>'
    '<geom name="v2" group="1" material="x"/><geom name="n"/></body>'
)


@pytest.mark.parametrize(
    "material",
    [
        None,
        ("t", "m", False),
        ("t", "m", True),
        ("t", "p_m", False),
    ],
    ids=["default", "custom", "shared", "already-prefixed"],
)
def test_golden_add_material(material: tuple[str, str, bool] | None) -> None:
    """add_material changes the tree, the material and returns elements like robosuite (check 6)."""

    def operation(module: Any, root: ET.Element) -> Any:
        custom = None
        if material is not None:
            tex_name, mat_name, shared = material
            custom = module.CustomMaterial(None, tex_name, mat_name, shared=shared)
        return module.add_material(root, "p_", custom)

    differential("add_material", ET.fromstring(E5), operation)
    collision_only = ET.fromstring('<body><geom group="0"/><geom/></body>')
    differential("add_material", collision_only, operation)
    root = ET.fromstring(E5)
    texture, mat, _, used = operation(ours, root)
    assert used
    if material is None:
        assert ET.tostring(texture, encoding="unicode") == (
            '<texture type="cube" builtin="flat" width="100" height="100" rgb1="1.0 1.0 1.0" '
            'rgb2="1.0 1.0 1.0" name="p_default_tex" />'
        )
        assert ET.tostring(mat) == b'<material texture="p_default_tex" name="p_default_mat" />'
        assert ET.tostring(root[0]) == b'<geom name="v" group="1" material="p_default_mat" />'
    if material == ("t", "p_m", False):
        assert ET.tostring(mat) == b'<material texture="t" name="p_m" />'


def test_golden_recolor_collision_geoms() -> None:
    """recolor_collision_geoms paints group 0/none geoms and drops materials (golden check 6)."""
    xml = (
        '<body><geom name="a" material="m"/><geom name="floor"/><geom name="v" group="1"/>'
        '<geom name="g3" group="3"/><geom name="z" group="0" rgba="1 1 1 1"/></body>'
    )

    def operation(module: Any, root: ET.Element) -> None:
        module.recolor_collision_geoms(root, [0.5, 0, 0, 1], lambda e: e.get("name") == "floor")

    differential("recolor_collision_geoms", ET.fromstring(xml), operation)
    root = ET.fromstring(xml)
    operation(ours, root)
    assert ET.tostring(root[0]) == b'<geom name="a" rgba="0.5 0 0 1" />'
    assert ET.tostring(root[4]) == b'<geom name="z" group="0" rgba="0.5 0 0 1" />'
    assert [e.get("rgba") for e in root[1:4]] == [None, None, None]


def test_tree_functions_keep_the_element_objects() -> None:
    """The tree functions change attributes on the same Element objects; none is replaced."""
    root = ET.fromstring(E2)
    before = list(root.iter())
    ours.add_prefix(root, "p_")
    ours.set_alpha(root, 0.5)
    ours.recolor_collision_geoms(root, ours.RED)
    ours.add_material(root, "p_")
    ours.scale_mjcf_model(root, ET.Element("asset"), 2, ours.get_elements, worldbody=root)
    assert all(a is b for a, b in zip(root.iter(), before, strict=True))
    assert root[0].get("rgba") == "1 0 0 1" and root[0].get("name") == "p_g"


def test_named_textures_and_relative_paths_need_robosuite(monkeypatch: pytest.MonkeyPatch) -> None:
    """Without robosuite, a relative path or a named texture raises MjcfLookupError."""
    import importlib.util

    real = importlib.util.find_spec
    monkeypatch.setattr(
        importlib.util,
        "find_spec",
        lambda name, *a: None if name == "robosuite" else real(name, *a),
    )
    with pytest.raises(MjcfLookupError, match="robosuite is not installed"):
        ours.xml_path_completion("textures/a.png")
    with pytest.raises(MjcfLookupError):
        ours.CustomMaterial("WoodDark", "t", "m")
    assert ours.xml_path_completion("/abs/a.png") == "/abs/a.png"
