"""Tests of ``mjcf_model.errors``."""

from __future__ import annotations

from pathlib import Path

import mujoco
import pytest

from mjcf_model import (
    Geom,
    MjcfError,
    MjcfIncludeCycleError,
    MjcfIncludeError,
    MjcfSecurityError,
    MjcfSyntaxError,
    MjcfValueError,
    Mujoco,
)
from mjcf_model.serializers import dumps, from_dict, load, loads
from mjcf_model.values import Unparsed

# -- Bad input raises an MjcfError subclass that says where (file, line, path) and what. -------


def _write(path: Path, text: str) -> Path:
    path.write_text(text, encoding="utf-8")
    return path


def test_malformed_xml(tmp_path: Path) -> None:
    """Unclosed tags name the file, the line and the innermost open element."""
    path = _write(tmp_path / "bad.xml", "<mujoco>\n  <worldbody>\n    <body name='b'>\n</mujoco>\n")
    with pytest.raises(MjcfSyntaxError) as caught:
        load(path)
    error = caught.value
    assert isinstance(error, ValueError) and isinstance(error, MjcfError)
    assert error.file == str(path) and error.line == 4
    assert error.path == "/mujoco/worldbody/body[@name='b']"
    assert str(error).startswith(f"{path}:4: /mujoco/worldbody/body[@name='b']: malformed XML")
    assert "mismatched tag" in str(error)


def test_wrong_number_of_values(tmp_path: Path) -> None:
    """``pos="0 1"`` names file, line, element path, attribute, expected and found."""
    path = _write(
        tmp_path / "m.xml",
        "<mujoco>\n<worldbody>\n<body name='arm'>\n<geom size='1'/>\n<geom pos='0 1'/>\n"
        "</body>\n</worldbody>\n</mujoco>\n",
    )
    geom = load(path).worldbody.bodies[0].geoms[1]
    assert geom.pos == Unparsed("0 1")
    with pytest.raises(MjcfValueError) as caught:
        list(geom.pos)
    assert str(caught.value) == (
        f"{path}:5: /mujoco/worldbody/body[@name='arm']/geom[2]: "
        "attribute 'pos': expected 3 numbers, found 2 in '0 1' "
        "(kept verbatim: MuJoCo may read what mjcf-model cannot)"
    )
    assert 'pos="0 1"' in dumps(load(path), canonical=True)


def test_non_number(tmp_path: Path) -> None:
    """A word where a number belongs names the attribute and the word."""
    path = _write(
        tmp_path / "m.xml", "<mujoco><worldbody><geom size='0.1 big'/></worldbody></mujoco>"
    )
    (geom,) = load(path).worldbody.geoms
    with pytest.raises(MjcfValueError) as caught:
        geom.size[0]
    assert caught.value.file == str(path)
    assert caught.value.line == 1
    assert caught.value.path == "/mujoco/worldbody/geom"
    assert "attribute 'size': expected a number, found 'big'" in str(caught.value)


def test_non_integer(tmp_path: Path) -> None:
    """An integer attribute rejects fractions, as MuJoCo does."""
    path = _write(tmp_path / "m.xml", "<mujoco><worldbody><geom group='1.5'/></worldbody></mujoco>")
    (geom,) = load(path).worldbody.geoms
    with pytest.raises(MjcfValueError, match=r"'group': expected an integer, found '1\.5'"):
        int(geom.group)
    with pytest.raises(MjcfValueError, match=r"expected an integer, found '1\.5'"):
        Geom(group="1.5")


def test_unknown_keyword(tmp_path: Path) -> None:
    """``type="cube"`` lists the keywords that exist."""
    path = _write(
        tmp_path / "m.xml", "<mujoco>\n<worldbody>\n<geom type='cube'/></worldbody></mujoco>"
    )
    (geom,) = load(path).worldbody.geoms
    assert geom.type == Unparsed("cube")
    with pytest.raises(MjcfValueError) as caught:
        geom.type.fail()
    message = str(caught.value)
    assert message.startswith(f"{path}:3: /mujoco/worldbody/geom: attribute 'type': ")
    assert "found 'cube'" in message and "'box'" in message and "'sphere'" in message


def test_missing_include(tmp_path: Path) -> None:
    """A missing included file is an OSError naming the include and where it was looked for."""
    path = _write(tmp_path / "main.xml", "<mujoco>\n  <include file='parts/arm.xml'/>\n</mujoco>")
    with pytest.raises(MjcfIncludeError) as caught:
        load(path, inline_includes=True)
    error = caught.value
    assert isinstance(error, OSError)
    assert error.file == str(path) and error.line == 2 and error.path == "/mujoco/include"
    assert "'parts/arm.xml' not found" in str(error)
    assert str(tmp_path / "parts" / "arm.xml") in str(error)


def test_include_cycle(tmp_path: Path) -> None:
    """Files that include each other are reported with the whole cycle."""
    _write(tmp_path / "a.xml", "<mujoco>\n<include file='b.xml'/>\n</mujoco>")
    _write(tmp_path / "b.xml", "<mujoco>\n\n<include file='a.xml'/>\n</mujoco>")
    with pytest.raises(MjcfIncludeCycleError) as caught:
        load(tmp_path / "a.xml", inline_includes=True)
    error = caught.value
    assert isinstance(error, ValueError) and not isinstance(error, OSError)  # as MuJoCo's
    assert error.file == str(tmp_path / "b.xml") and error.line == 3
    assert "include cycle" in str(error)
    assert str(tmp_path / "a.xml") in str(error) and str(tmp_path / "b.xml") in str(error)


def test_kept_include_is_not_read(tmp_path: Path) -> None:
    """By default an include of a missing file loads: it stays an include."""
    path = _write(tmp_path / "main.xml", "<mujoco><include file='nowhere.xml'/></mujoco>")
    assert load(path).children[0].file == "nowhere.xml"  # type: ignore[attr-defined]


def test_doctype_refused() -> None:
    """A DTD is refused before anything is expanded."""
    text = (
        '<?xml version="1.0"?>\n<!DOCTYPE mujoco [\n<!ENTITY lol "lol">\n]>\n'
        "<mujoco model='&lol;'/>"
    )
    with pytest.raises(MjcfSecurityError) as caught:
        loads(text)
    assert caught.value.line == 2 and "DTD" in str(caught.value)


def test_external_entity_refused(tmp_path: Path) -> None:
    """An external entity is never fetched or read."""
    secret = _write(tmp_path / "secret.txt", "secret")
    text = f'<!DOCTYPE m [<!ENTITY x SYSTEM "file://{secret}">]><mujoco model="&x;"/>'
    with pytest.raises(MjcfSecurityError):
        loads(text)


def test_undefined_entity_is_read_as_text_like_mujoco() -> None:
    """Without a DTD, MuJoCo's parser reads ``&x;`` as those three characters; so do we."""
    text = "<mujoco model='&x; & &amp; &#65;'/>"
    assert mujoco.MjModel.from_xml_string(text).names.split(b"\0")[0] == b"&x; & & A"
    assert loads(text).model == "&x; & & A"
    assert loads(dumps(loads(text))).model == "&x; & & A"


def test_wrong_root() -> None:
    """A file that is not MJCF says what root it found."""
    with pytest.raises(MjcfSyntaxError, match="expected a <mujoco> root element, found <robot>"):
        loads("<robot name='r'/>")


def test_direct_construction_errors() -> None:
    """Building nodes in Python validates the same way as reading."""
    with pytest.raises(MjcfValueError, match="expected 3 numbers, found 2"):
        Geom(pos=[0, 1])
    with pytest.raises(MjcfValueError, match="found 'cube'"):
        Geom(type="cube")
    with pytest.raises(MjcfValueError, match="children must be nodes"):
        Mujoco(children=["<worldbody/>"])  # type: ignore[list-item]


def test_bad_dict() -> None:
    """A dict that describes no node is a ValueError saying why."""
    with pytest.raises(MjcfValueError, match="not a node dict"):
        from_dict({"_node": "NoSuchNode"})


#: Each error class and the builtin exception it also is: what ``except`` clauses
#: written for the standard library catch.
ERROR_BUILTINS = {
    "MjcfSyntaxError": ValueError,
    "MjcfValueError": ValueError,
    "MjcfLookupError": KeyError,
    "MjcfFileError": OSError,
    "MjcfFileNotFoundError": FileNotFoundError,
    "MjcfIncludeError": OSError,
    "MjcfIncludeCycleError": ValueError,
    "MjcfAssetError": OSError,
    "MjcfCompileError": ValueError,
    "MjcfRenderError": RuntimeError,
    "MjcfSecurityError": ValueError,
}


def test_every_error_class_is_one_builtin_error() -> None:
    """Every ``MjcfError`` subclass derives from the builtin listed for it, and no other one."""
    import mjcf_model.errors as errors

    classes = {
        name: value
        for name in errors.__all__
        if isinstance(value := getattr(errors, name), type) and issubclass(value, MjcfError)
    }
    assert set(classes) - {"MjcfError"} == set(ERROR_BUILTINS)
    builtins = (ValueError, KeyError, OSError, RuntimeError)
    for name, builtin in ERROR_BUILTINS.items():
        cls = classes[name]
        assert issubclass(cls, builtin)
        others = [b for b in builtins if issubclass(cls, b) and not issubclass(builtin, b)]
        assert others == [], f"{name} is also {others}"
        # the message is the location and detail, never repr()-quoted (as KeyError would)
        assert str(cls("detail", file="m.xml", line=2)) == "m.xml:2: detail"
