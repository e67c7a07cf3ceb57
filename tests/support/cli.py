"""Running ``mjcf-model`` as a user runs it, and the models the command-line tests share."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

#: A model with a default class, written untidily (a one-attribute edit is made to it).
UNTIDY = """<mujoco model="arm">
<default><default class="red"><geom rgba="1 0 0 1"/></default></default>
<worldbody>   <body name="arm" childclass="red"><joint name="elbow" type="hinge"/>
<geom name="upper" size="0.10  0.2" type="capsule"/><site name="tip" pos="0 0 .3"/></body>
<camera name="front" pos="0 -2 0.3" xyaxes="1 0 0 0 0 1"/><light pos="0 0 3"/>
</worldbody></mujoco>
"""


def run(
    *arguments: str, stdin: str | None = None, cwd: Path | None = None
) -> subprocess.CompletedProcess[str]:
    """``mjcf-model ARGUMENTS`` in a fresh process, as a user runs it."""
    return subprocess.run(
        [sys.executable, "-m", "mjcf_model", *arguments],
        input=stdin,
        capture_output=True,
        text=True,
        check=False,
        env={k: v for k, v in os.environ.items() if k != "MUJOCO_GL"},
    )


#: The base: degrees and a z-y-x Euler sequence (euler= is read so), and a turned table.
BASE = """<mujoco model="base">
  <compiler angle="degree" eulerseq="zyx"/>
  <worldbody>
    <geom name="floor" type="plane" size="5 5 0.1"/>
    <body name="table" pos="0.3 -0.2 0.5" euler="25 0 0">
      <geom type="box" size="0.3 0.3 0.02"/>
    </body>
  </worldbody>
</mujoco>
"""


#: A free-floating box with a lid on it, turned; no keyframes.
FREE = """<mujoco model="box">
  <worldbody>
    <body name="box" pos="0.1 0.2 0.3" quat="0.9 0.1 0.3 0.2">
      <freejoint/>
      <geom type="box" size="0.1 0.1 0.1"/>
      <body name="lid" pos="0 0.05 0.12" euler="0.2 0 0.4">
        <geom type="box" size="0.1 0.1 0.01"/>
      </body>
    </body>
  </worldbody>
</mujoco>
"""


#: A fixed-base arm (radians) with a keyframe.
ARM = """<mujoco model="arm">
  <worldbody>
    <body name="base" pos="0 0 0.1" euler="0 0 0.3">
      <geom type="cylinder" size="0.05 0.05"/>
      <body name="upper" pos="0 0 0.1" euler="0.4 0 0">
        <joint name="shoulder" axis="0 1 0"/>
        <geom type="capsule" fromto="0 0 0 0 0 0.3" size="0.03"/>
        <body name="fore" pos="0 0 0.3" euler="0 0.5 0">
          <joint name="elbow" axis="0 1 0"/>
          <geom type="capsule" fromto="0 0 0 0 0 0.25" size="0.02"/>
        </body>
      </body>
    </body>
  </worldbody>
  <keyframe><key name="bent" qpos="0.5 -1"/></keyframe>
</mujoco>
"""


def _files(tmp_path: Path) -> dict[str, Path]:
    """The base, the free box and the arm, each written to its own file in ``tmp_path``."""
    files = {name: tmp_path / f"{name}.xml" for name in ("base", "free", "arm")}
    for name, text in (("base", BASE), ("free", FREE), ("arm", ARM)):
        files[name].write_text(text)
    return files
