"""Tests of ``mjcf_model.bridge.compiling``."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest

from benchmarks.inputs import package_dir
from mjcf_model import MjcfAssetError, MjcfCompileError, compiled, scaled
from mjcf_model.bridge import compiling
from mjcf_model.bridge.compare import model_differences, path_fields
from mjcf_model.files.png import png_bytes
from mjcf_model.files.provenance import file_references
from mjcf_model.serializers import bundling, dumps, load, loads
from tests.support.model_files import ROBOT, _same, obj_mesh
from tests.support.skin_files import _skin_model

# -- ``compiled`` lets MuJoCo read the files that exist on disk, and compiles what MuJoCo would.
#
# Each model is written into a folder with its mesh, texture, included and asset
# ``<model>`` files; MuJoCo loading the file (``MjModel.from_xml_path``) is the
# referee, and ``compiled(load(path))`` must give the same model (but for the file paths it records,
# ``path_fields``) while reading none
# of those files itself (they go to MuJoCo by absolute path, so its cache serves
# them). Files given in ``assets=`` and files that are not on disk still go through
# MuJoCo's asset dictionary.


def _tetrahedron(size: float) -> bytes:
    """An OBJ tetrahedron with edges ``size`` long along the axes."""
    points = f"v 0 0 0\nv {size} 0 0\nv 0 {size} 0\nv 0 0 {size}\n"
    return (points + "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n").encode()


def _checker() -> bytes:
    """A 4 x 4 PNG of two colours."""
    pixels = np.zeros((4, 4, 3), dtype=np.uint8)
    pixels[::2, ::2] = (255, 0, 0)
    return png_bytes(pixels)


def _write(folder: Path, files: dict[str, bytes | str]) -> None:
    for name, data in files.items():
        path = folder / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(data.encode() if isinstance(data, str) else data)


@pytest.fixture
def no_reads(monkeypatch: pytest.MonkeyPatch) -> list[str]:
    """The files ``compiled`` reads itself (it should leave those on disk to MuJoCo)."""
    reads: list[str] = []
    read = bundling._read

    def counting(reference: bundling.FileReference, assets: dict[str, bytes]) -> bytes:
        reads.append(reference.text)
        return read(reference, assets)

    monkeypatch.setattr(bundling, "_read", counting)
    return reads


_MESH_BODY = """<worldbody><body><geom type="mesh" mesh="tet"/>
<geom type="box" size="0.1 0.1 0.1" material="checks" pos="1 0 0"/></body></worldbody>"""

#: Models whose files MuJoCo finds through each folder setting, by what they test.
FOLDER_CASES: dict[str, dict[str, bytes | str]] = {
    "plain paths": {
        "model.xml": f"""<mujoco><asset><mesh name="tet" file="parts/tet.obj"/>
            <texture name="checks" type="2d" file="parts/checks.png"/>
            <material name="checks" texture="checks"/></asset>{_MESH_BODY}</mujoco>""",
        "parts/tet.obj": _tetrahedron(0.2),
        "parts/checks.png": _checker(),
    },
    "meshdir and texturedir": {
        "model.xml": f"""<mujoco><compiler meshdir="meshes" texturedir="../textures"/>
            <asset><mesh name="tet" file="tet.obj"/>
            <texture name="checks" type="2d" file="checks.png"/>
            <material name="checks" texture="checks"/></asset>{_MESH_BODY}</mujoco>""",
        "meshes/tet.obj": _tetrahedron(0.3),
        "../textures/checks.png": _checker(),
    },
    "assetdir": {
        "model.xml": f"""<mujoco><compiler assetdir="assets"/>
            <asset><mesh name="tet" file="tet.obj"/>
            <texture name="checks" type="2d" file="checks.png"/>
            <material name="checks" texture="checks"/></asset>{_MESH_BODY}</mujoco>""",
        "assets/tet.obj": _tetrahedron(0.4),
        "assets/checks.png": _checker(),
    },
    "strippath": {
        "model.xml": f"""<mujoco><compiler meshdir="meshes" texturedir="meshes"
            strippath="true"/><asset><mesh name="tet" file="C:/elsewhere/tet.obj"/>
            <texture name="checks" type="2d" file="/far/away/checks.png"/>
            <material name="checks" texture="checks"/></asset>{_MESH_BODY}</mujoco>""",
        "meshes/tet.obj": _tetrahedron(0.5),
        "meshes/checks.png": _checker(),
    },
    "an include in another folder": {
        "model.xml": """<mujoco><compiler meshdir="meshes"/>
            <include file="parts/assets.xml"/>
            <worldbody><include file="parts/body.xml"/></worldbody></mujoco>""",
        "parts/assets.xml": """<mujoco><asset><mesh name="tet" file="tet.obj"/>
            <texture name="checks" type="2d" file="textures/checks.png"/>
            <material name="checks" texture="checks"/></asset></mujoco>""",
        "parts/body.xml": f"<mujoco>{_MESH_BODY.replace('worldbody', 'body')}</mujoco>",
        "meshes/tet.obj": _tetrahedron(0.6),
        "textures/checks.png": _checker(),
    },
}


@pytest.mark.parametrize("case", list(FOLDER_CASES))
def test_compiled_is_what_mujoco_loads_and_reads_no_file_itself(
    case: str, tmp_path: Path, no_reads: list[str]
) -> None:
    """MuJoCo compiles the same model from the file and from ``compiled``, which reads nothing."""
    folder = tmp_path / "robot"
    folder.mkdir()
    _write(folder, FOLDER_CASES[case])
    path = folder / "model.xml"
    expected = mujoco.MjModel.from_xml_path(str(path))
    before = sorted(tmp_path.rglob("*"))
    for inline_includes in (False, True):
        result = compiled(load(path, inline_includes=inline_includes))
        assert model_differences(result, expected, ignore=path_fields()) == [], inline_includes
    assert result.nmesh == 1 and result.ntex == 1
    assert no_reads == []
    assert sorted(tmp_path.rglob("*")) == before  # nothing written


def test_asset_models_are_read_from_their_own_folder(tmp_path: Path) -> None:
    """An asset ``<model>`` goes to MuJoCo as text; its mesh, in its own folder, by path."""
    _write(
        tmp_path,
        {
            "scene.xml": """<mujoco><asset><model name="arm" file="arm/arm.xml"/></asset>
                <worldbody><body name="mount"><attach model="arm" body="link" prefix="a_"/>
                </body></worldbody></mujoco>""",
            "arm/arm.xml": """<mujoco><compiler meshdir="meshes"/>
                <asset><mesh name="tet" file="tet.obj"/></asset>
                <worldbody><body name="link"><geom type="mesh" mesh="tet"/></body></worldbody>
                </mujoco>""",
            "arm/meshes/tet.obj": _tetrahedron(0.25),
        },
    )
    path = tmp_path / "scene.xml"
    expected = mujoco.MjModel.from_xml_path(str(path))
    assert model_differences(compiled(load(path)), expected, ignore=path_fields()) == []
    assert expected.nmesh == 1


def test_files_given_in_assets_win_over_the_files_on_disk(
    tmp_path: Path, no_reads: list[str]
) -> None:
    """``assets=`` replaces a file on disk: MuJoCo compiles the given bytes."""
    _write(tmp_path / "kept", FOLDER_CASES["plain paths"])
    _write(tmp_path / "other", {**FOLDER_CASES["plain paths"], "parts/tet.obj": _tetrahedron(2.0)})
    model = load(tmp_path / "kept" / "model.xml")
    given = compiled(model, assets={"parts/tet.obj": _tetrahedron(2.0)})
    assert no_reads == ["parts/tet.obj"]
    expected = mujoco.MjModel.from_xml_path(str(tmp_path / "other" / "model.xml"))
    assert model_differences(given, expected, ignore=path_fields()) == []
    assert model_differences(compiled(model), expected, ignore=path_fields()) != []


def test_a_model_built_in_code_takes_its_files_from_assets_or_the_working_folder(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Without a folder, relative paths resolve from the working folder; missing ones say so."""
    text = '<mujoco><asset><mesh name="tet" file="tet.obj"/></asset><worldbody>'
    text += '<geom type="mesh" mesh="tet"/></worldbody></mujoco>'
    model = loads(text)
    monkeypatch.chdir(tmp_path)
    with pytest.raises(MjcfAssetError, match=r"<mesh file='tet\.obj'>: cannot read"):
        compiled(model)
    assert compiled(model, assets={"tet.obj": _tetrahedron(0.1)}).nmesh == 1
    (tmp_path / "tet.obj").write_bytes(_tetrahedron(0.1))
    from_folder = compiled(model)
    expected = mujoco.MjModel.from_xml_string(text)
    assert model_differences(from_folder, expected, ignore=path_fields()) == []


@pytest.mark.parametrize("factor", [0.8, 1.1, 1.17])
def test_a_big_inline_skin_compiles_from_a_file_to_the_model_its_text_compiles_to(
    factor: float,
) -> None:
    """dm_control's dog, scaled: its skin goes to MuJoCo as a binary file, and nothing changes."""
    path = package_dir("dm_control") / "suite/dog.xml"
    model = scaled(load(path, inline_includes=True), factor, mass="volume")
    bundle = bundling.bundled(model)
    given, files = compiling._skins_as_files(bundle.model, bundle.files)
    assert [name for name in files if name.endswith(".skn")] == ["mjcf-model-skin-0.skn"]
    assert "skin_vert" not in dumps(given) and len(dumps(given)) < len(dumps(bundle.model)) / 10
    from_text = mujoco.MjModel.from_xml_string(dumps(bundle.model), bundle.files)
    assert model_differences(compiled(model), from_text, ignore=path_fields()) == []


def test_an_unnamed_or_small_skin_stays_inline() -> None:
    """MuJoCo would name an unnamed skin after its file; a small one is not worth a file."""
    vertices = [float(i) / 7 for i in range(9000)]
    for model in (loads(_skin_model(vertices, name=None)), loads(_skin_model(vertices[:30]))):
        assert compiling._skins_as_files(model, {}) == (model, {})
    named = loads(_skin_model(vertices))
    assert compiling._skins_as_files(named, {})[0] != named
    text = mujoco.MjModel.from_xml_string(_skin_model(vertices))
    assert model_differences(compiled(named), text, ignore=path_fields()) == []


# -- Where a model's files are: compiled in memory, dumped elsewhere, exported, MuJoCo as
#    referee.


def test_compiled_finds_files_through_the_folder(robot: Path, tmp_path: Path) -> None:
    """A model compiled in memory equals MuJoCo's compile of the file, from any working folder."""
    expected = mujoco.MjModel.from_xml_path(str(robot))
    model = load(robot)
    assert _same(compiled(model), expected) == []
    assert compiled(model).mesh_vertnum.tolist() == [6]
    assert [str(r.path) for r in file_references(model)] == [
        str(robot.parent.resolve() / "assets" / "link.obj")
    ]


def test_compiled_takes_files_from_the_assets_mapping() -> None:
    """A model built in code takes its files from ``assets``, by path with or without the folder."""
    model = loads(ROBOT)
    assert compiled(model, assets={"link.obj": obj_mesh(7).encode()}).mesh_vertnum.tolist() == [7]
    with_folder = {"assets/link.obj": obj_mesh(5).encode()}
    assert compiled(model, assets=with_folder).mesh_vertnum.tolist() == [5]


def test_compiled_says_which_file_is_missing_and_what_mujoco_rejects() -> None:
    """A missing file raises MjcfAssetError naming it; MuJoCo's refusal is MjcfCompileError."""
    with pytest.raises(MjcfAssetError, match=r"link\.obj.*assets="):
        compiled(loads(ROBOT))
    with pytest.raises(MjcfCompileError, match="MuJoCo rejects the model"):
        compiled(loads('<mujoco><worldbody><geom type="mesh" mesh="no"/></worldbody></mujoco>'))


def test_a_model_compiled_again_is_written_once_where_mujoco_reads_its_files(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Compiling one model again reuses its text, per working folder; read files are not kept.

    The text names every file by absolute path, so MuJoCo reads what is on disk each time;
    a relative path of a model built in code resolves from the working folder of each call.
    """
    text = '<mujoco><asset><mesh name="tet" file="tet.obj"/></asset><worldbody>'
    text += '<geom type="mesh" mesh="tet"/></worldbody></mujoco>'
    model = loads(text)
    for folder, points in (("four", 4), ("six", 6)):
        (tmp_path / folder).mkdir()
        (tmp_path / folder / "tet.obj").write_text(obj_mesh(points))
    written: list[str] = []
    real_dumps = compiling.dumps

    def counting_dumps(node: object, **options: object) -> str:
        written.append("once")
        return real_dumps(node, **options)  # type: ignore[arg-type]

    monkeypatch.setattr(compiling, "dumps", counting_dumps)
    monkeypatch.chdir(tmp_path / "four")
    assert [compiled(model).mesh_vertnum[0] for _ in range(3)] == [4, 4, 4]
    assert len(written) == 1
    monkeypatch.chdir(tmp_path / "six")
    assert compiled(model).mesh_vertnum[0] == 6 and len(written) == 2
    # files handed over in memory are bundled at every call: they may change
    for points in (5, 7):
        assets = {"tet.obj": obj_mesh(points).encode()}
        assert compiled(model, assets=assets).mesh_vertnum[0] == points
    assert len(written) == 4
