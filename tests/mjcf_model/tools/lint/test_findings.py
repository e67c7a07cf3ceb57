"""Tests of ``mjcf_model.tools.lint.findings``: how a finding reads, and the rule registry."""

from __future__ import annotations

import json

import pytest

from mjcf_model.tools.lint.findings import RULES, Finding, rule


def test_a_finding_reads_like_a_compilers_message_and_goes_to_json() -> None:
    """``file:line: path: CODE message``, leaving out what it lacks; JSON keeps every field."""
    full = Finding(
        file="a.xml", line=3, path="/mujoco", rule="A401", severity="warning", message="m"
    )
    assert str(full) == "a.xml:3: /mujoco: A401 m"
    bare = Finding(file=None, line=None, path=None, rule="A401", severity="warning", message="m")
    assert str(bare) == "A401 m"
    assert json.loads(json.dumps(full.to_dict())) == {
        "file": "a.xml",
        "line": 3,
        "path": "/mujoco",
        "rule": "A401",
        "severity": "warning",
        "message": "m",
    }


def test_every_rule_has_a_code_a_name_and_a_sentence_and_no_code_registers_twice() -> None:
    """The registry holds the rule modules' rules; a second ``K101`` is refused."""
    assert len(RULES) >= 10
    for code, found in RULES.items():
        assert found.code == code and len(code) == 4 and code[1:].isdigit()
        assert found.name and found.summary and found.severity in ("error", "warning")
    with pytest.raises(ValueError, match="registered twice"):
        rule("K101", "again", "error", "x")(lambda subject: [])
